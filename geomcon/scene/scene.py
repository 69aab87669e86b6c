"""A scene: the lazy construction DAG of one textbook construction.

Steps are added in drawing order and may only refer to steps added before them, so insertion order is a
topological order. Evaluation culls to the dependencies of what is asked for, walks them in that order and
computes each step once (memoised). ``stats`` tells how many steps exist and how many were computed, so
laziness is observable: asking for the answers computes no annotation, asking for frame k computes no
step after k.

Examples
--------
>>> from geomcon.geometry import Point, circle, circle_circle, LeftOf
>>> sc = Scene("demo")
>>> A = sc.given("A", Point(0, 0))
>>> D = sc.given("D", Point(8, 0))
>>> cA = sc.add("cA", circle, A, 5.0, caption=("Circle about A, r = 5", "以 A 为圆心、5 为半径作圆"))
>>> cD = sc.add("cD", circle, D, 5.0, caption=("Circle about D, r = 5", "以 D 为圆心、5 为半径作圆"))
>>> C = sc.add("C", circle_circle, cA, cD, branch=LeftOf(A, D), caption=("They meet at C", "两圆交于 C"))
>>> sc.value("C")
Point(x=4.0, y=3.0)
>>> sc.stats
{'steps_total': 5, 'steps_evaluated': 5}
>>> sc.caption("C")[0]
'They meet at C (left of the directed line A→D)'
"""
from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any, Callable, Iterable, Iterator

from ..errors import GeomconError, NoIntersection, Unbuildable
from ..geometry.branch import Branch
from ..geometry.primitives import Circle, Line, Point
from ..render.zh import en_remark, zh_remark
from .compiled import order_of
from .step import Ref, Role, Step, collect_refs, constant as _constant


def _resolve(x: Any, memo: dict[str, Any]) -> Any:
    t = type(x)
    if t is Ref:
        return memo[x[0]]
    if t is tuple:
        return tuple(_resolve(y, memo) for y in x)
    if t is list:
        return [_resolve(y, memo) for y in x]
    if isinstance(x, Branch):
        return x.with_points(tuple(_resolve(y, memo) for y in x.refs()))
    return x


_PLAIN, _TOP, _DEEP = 0, 1, 2
"""How a step's arguments are resolved: no references at all; references only as top-level positional
arguments; references anywhere (nested tuples, lists, keyword values)."""


def _describe(obj: Any) -> str:
    if isinstance(obj, Circle):
        return f"circle(({obj.center.x:.6g}, {obj.center.y:.6g}), r={obj.r:.6g})"
    if isinstance(obj, Line):
        return f"line through ({obj.point.x:.6g}, {obj.point.y:.6g}) dir ({obj.direction.x:.4g}, {obj.direction.y:.4g})"
    return repr(obj)


def _no_meet_message(a: Any, b: Any) -> str:
    if isinstance(a, Circle) and isinstance(b, Circle):
        d = abs(b.center - a.center)
        if d > a.r + b.r:
            why = f"distance of centres {d:.6g} > r1 + r2 = {a.r + b.r:.6g}"
        else:
            why = f"distance of centres {d:.6g} < |r1 - r2| = {abs(a.r - b.r):.6g}"
        return f"{_describe(a)} and {_describe(b)} do not meet: {why}"
    if isinstance(a, Line) and isinstance(b, Circle):
        dist = abs(a.direction.cross(b.center - a.point))
        return f"{_describe(a)} misses {_describe(b)}: distance {dist:.6g} > r = {b.r:.6g}"
    return f"{_describe(a)} and {_describe(b)} do not meet"


class PlanMiss(Exception):
    """A planned scene was asked for a step its plan left out (a recipe built a new shape of scene): the
    solver builds the scene again unplanned, which teaches the plan the missing steps. Never a user error."""


_LEAN: ContextVar[tuple[str, bool] | None] = ContextVar("geomcon_lean_scenes", default=None)


class LeanScenes:
    """Within this block, new scenes are *lean* and, when ``plan`` names the work (a recipe's name), *planned*.

    A lean scene counts but does not store its annotation steps (angle arcs, ground symbols, dimensions: only a
    drawing needs them). A planned scene also skips every step that no scene of the same plan and title has
    needed so far: the first solve of a recipe learns which steps its answers need (the evaluation plan),
    later solves build only those. When a solve needs a step outside its plan, the scene completes itself
    (:meth:`Scene.rebuild_with`) or raises :class:`PlanMiss`, and the work is done again with ``learn=True``
    (every step but the annotations, and what it evaluates is added to the plan); so the plan only ever saves
    work and never changes a value. Solving for answers builds planned scenes; a drawing completes them.

    Examples
    --------
    >>> from geomcon.geometry import Point
    >>> with LeanScenes():
    ...     sc = Scene("demo")
    >>> A = sc.given("A", Point(0, 0))
    >>> _ = sc.add("mark", repr, A, role=Role.ANNOTATION)
    >>> sc.lean, "mark" in sc, sc.stats["steps_total"]
    (True, True, 2)
    """

    __slots__ = ("_mode", "_token")

    def __init__(self, plan: str = "", *, learn: bool = False) -> None:
        self._mode = (plan, learn)

    def __enter__(self) -> None:
        self._token = _LEAN.set(self._mode)

    def __exit__(self, *exc: object) -> None:
        _LEAN.reset(self._token)


lean_scenes = LeanScenes
"""The same as :class:`LeanScenes` (a lower-case name for use in ``with``)."""


@contextmanager
def _full() -> Iterator[None]:
    token = _LEAN.set(None)
    try:
        yield
    finally:
        _LEAN.reset(token)


_KEEP: dict[tuple[str, str], set[str]] = {}
"""Evaluation plans learned across solves: (plan name, scene title) → the keys some solve has evaluated."""

_PLANS: dict[tuple[int, tuple[str, ...]], list[str]] = {}
"""Culled, ordered evaluation lists reused across scenes: (the scene's structure signature, the keys asked
for) → the keys to compute, in order."""
_CACHE_MAX = 4096
_TAPE = "§"
"""The first character of a replayed tape's own steps (:data:`.tape.PREFIX`)."""
_ANNOTATION = Role.ANNOTATION
_new_ref = tuple.__new__


def _names(caption: str, label: str | None) -> bool:
    """Whether ``caption`` names the point ``label`` (not as the start of a longer name: "B1" is not named by
    "B12", "B1′" or "B1*"; "C1" is by "AC1").

    >>> _names("B1, B2 on ee with B1B2 = 308", "B2"), _names("Draw AB1′", "B1"), _names("Plot s(δ)", None)
    (True, False, False)
    """
    if not label:
        return False
    import re
    return re.search(r"(?<![a-z])" + re.escape(label) + r"(?![0-9′″‴'*a-z])", caption) is not None


class Scene:
    """An ordered mapping key → :class:`Step` with lazy, memoised evaluation.

    Each step is stored as a light record (operation, arguments, the keys it depends on, computed once when
    the step is added); the :class:`Step` object a drawing reads is made on demand. The structure of the scene
    (keys and dependencies) is summed up in a signature as it is built, and the evaluation plan of a request
    (which steps, in which order) is cached by that signature across scenes.

    Parameters
    ----------
    title : str
        Title of the construction (used by the drawing).
    """

    def __init__(self, title: str = "") -> None:
        self.title = title
        mode = _LEAN.get()
        self.lean = mode is not None
        self._rec: dict[str, tuple] = {}
        self._step: dict[str, Step] = {}
        self._memo: dict[str, Any] = {}
        self._skip: set[str] = set()
        self._sig = 0
        self._learn: set[str] | None = None     # the plan this scene teaches (an unplanned lean scene)
        self._keep: set[str] | None = None      # the plan this scene follows (a planned scene)
        self._rebuild: Callable[[], Scene] | None = None
        self._stale = False                     # a replayed tape: captions and labels are the recording's
        self._tape: Any = None
        self._pending: tuple | None = None      # a compiled replay's other steps, stored when first read
        if mode is not None and mode[0]:
            known = _KEEP.get((mode[0], title))
            if known is None or mode[1]:
                if known is None:
                    if len(_KEEP) >= _CACHE_MAX:
                        _KEEP.clear()
                    known = _KEEP[(mode[0], title)] = set()
                self._learn = known
            else:
                self._keep = known

    @classmethod
    def replayed(cls, tape: Any, memo: dict[str, Any], pending: tuple | None = None) -> Scene:
        """A lean scene following the plan of ``tape`` (:mod:`.tape`) made of its recorded steps, its memo
        holding the tape's own steps (and, after a compiled plan ran on it, the steps asked for: ``pending`` is
        what that run returned, :meth:`settle`). Its captions, labels and step objects are the recording's: it
        completes itself (:meth:`rebuild_with`) before any of them is read."""
        sc = cls.__new__(cls)
        sc.title, sc.lean, sc._rec, sc._step, sc._memo = tape.title, True, tape.rec, {}, memo
        sc._skip, sc._sig, sc._learn, sc._keep, sc._rebuild = tape.skip, tape.sig, None, tape.keep, None
        sc._stale, sc._tape, sc._pending = True, tape, pending
        return sc

    def settle(self) -> None:
        """Store in the memo the steps a compiled replay computed besides those asked for (computed again from
        the same inputs under the run's tolerance, their objects made now, in the plan's order; the run left
        ``(fill, tol)`` for it, :func:`.compiled.compile_plan`).
        Everything that reads the memo beyond an evaluation's answers settles first: ``stats`` counts them, a
        later evaluation reuses them, a drawing completes the scene around them."""
        if self._pending is not None:
            fill, tol = self._pending
            self._pending = None
            fill(self._memo, tol)

    def unplanned(self) -> bool:
        """True unless this scene follows a plan (it stores every step but, when lean, the annotations)."""
        return self._keep is None

    def rebuild_with(self, build: Callable[[], Scene]) -> None:
        """Let a lean or planned scene complete itself: when a step it skipped is asked for (a drawing, an
        annotation, a step outside the plan), ``build()`` makes the same scene in full and this scene takes its
        steps, keeping every value computed so far (the same steps on the same givens give the same values).
        Without it, asking for a skipped step raises :class:`PlanMiss`."""
        self._rebuild = build

    def complete(self) -> Scene:
        """This scene with every step stored (built again in full once if it was lean); returns ``self``."""
        if self.lean or self._keep is not None:
            self._upgrade(None)
        return self

    def _upgrade(self, key: Any) -> None:
        if self._rebuild is None:
            raise PlanMiss(key)
        if self._pending is not None:
            self.settle()
        with _full():
            full = self._rebuild()
        if full.title != self.title or full.lean:
            raise AssertionError(f"rebuilding scene {self.title!r} gave {full.title!r}")
        self._rec, self._skip, self._sig, self._step = full._rec, full._skip, full._sig, {}
        if "_read" in full.__dict__:
            self._read = full._read
        self._learn = self._learn if self._keep is None else self._keep
        self.lean, self._keep, self._rebuild = False, None, None
        if self._stale:                      # the tape's own steps are not the recipe's
            memo = self._memo                # in place: an evaluation under way holds this dict
            for k in [k for k in memo if k[:1] == _TAPE]:
                del memo[k]
            # the steps the recipe evaluates while it builds (a branch decided by a step's value) were computed
            # by the tape as its own steps: they count as evaluated, as on the planned path, so that stats do
            # not depend on whether an earlier solve taped the recipe (same givens: the same values)
            for k, v in full._memo.items():
                if k not in memo:
                    memo[k] = v
            self._stale, self._tape = False, None

    # ------------------------------------------------------------------ building
    def add(self, key: str, op: Callable[..., Any], *args: Any, caption: tuple[str, str] = ("", ""),
            role: Role = Role.CONSTRUCTION, style: str = "", label: str | None = None,
            branch: Branch | None = None, visible: bool = True, unit: str = "", optional: bool = False,
            **kwargs: Any) -> Ref:
        """Add a step and return a :class:`Ref` to it.

        Raises
        ------
        KeyError
            When ``key`` exists already or a reference names a step not yet added.
        """
        rec = self._rec
        if key in rec or key in self._skip:
            raise KeyError(f"step '{key}' defined twice")
        keep = self._keep
        if (keep is not None and key not in keep) or (role is _ANNOTATION and self.lean):
            self._skip.add(key)
            return _new_ref(Ref, (key,))
        mode = _PLAIN
        deps: list[str] = []
        for a in args:
            t = type(a)
            if t is Ref:
                mode = _TOP
                deps.append(a[0])
            elif t is float or t is int or t is str or t is Point:
                continue
            elif t is tuple or t is list or isinstance(a, Branch):
                mode = _DEEP
                break
        if kwargs and mode != _DEEP:
            for a in kwargs.values():
                t = type(a)
                if t is Ref or t is tuple or t is list or isinstance(a, Branch):
                    mode = _DEEP
                    break
        if mode == _DEEP:
            deps = []
            collect_refs(args, deps)
            collect_refs(tuple(kwargs.values()), deps)
        brefs: tuple = ()
        if branch is not None:
            brefs = branch.refs()
            for r in brefs:
                if type(r) is Ref:
                    deps.append(r[0])
                elif type(r) is not Point:
                    collect_refs(r, deps)
        if not self.lean:
            # a full scene checks its references as it is built; a lean one finds a missing step when it
            # culls (a plan that skipped a needed step completes the scene there)
            missing = [d for d in deps if d not in rec]
            if missing:
                raise KeyError(f"step '{key}' refers to unknown step(s) {missing}")
        rec[key] = (op, args, kwargs, mode, branch, brefs, optional, deps,
                    (caption, role, style, label, visible, unit))
        self._sig = hash((self._sig, key, *deps))
        return _new_ref(Ref, (key,))

    def given(self, key: str, value: Any, *, caption: tuple[str, str] = ("", ""), style: str = "given",
              label: str | None = None, visible: bool = True, unit: str = "") -> Ref:
        """Add a given value (a step whose operation returns ``value``)."""
        return self.add(key, _constant, value, caption=caption, role=Role.GIVEN, style=style,
                        label=label if label is not None else (key if isinstance(value, Point) else None),
                        visible=visible, unit=unit)

    def given_at(self, key: str, x: Any, y: Any, *, caption: tuple[str, str] = ("", ""), style: str = "given",
                 label: str | None = None, visible: bool = True) -> Ref:
        """Add a given point ``(x, y)`` made by the step itself, so that a recipe taped with symbolic givens
        (:mod:`.tape`) can place it: ``sc.given_at("D", AD, 0.0)`` is ``sc.given("D", Point(AD, 0.0))``."""
        return self.add(key, Point, x, y, caption=caption, role=Role.GIVEN, style=style,
                        label=label if label is not None else key, visible=visible)

    # ------------------------------------------------------------------ reading
    def __contains__(self, key: str) -> bool:
        if key in self._rec or key in self._skip:
            return True
        if self._rebuild is not None and (self.lean or self._keep is not None):
            self.complete()          # a drawing-only step a lean scene never added
            return key in self._rec
        return False

    def __len__(self) -> int:
        return len(self._rec)

    def __getitem__(self, key: str) -> Step:
        step = self._step.get(key)
        if step is None:
            if self._stale:
                self.complete()
            if key in self._skip or (key not in self._rec and self._rebuild is not None
                                     and (self.lean or self._keep is not None)):
                self._upgrade(key)
            op, args, kwargs, _, branch, _, optional, _, meta = self._rec[key]
            caption, role, style, label, visible, unit = meta
            computed = type(caption) is Ref          # computed when read (see :meth:`caption`): not kept
            if computed:
                caption = self.value(caption[0])
            step = Step(key, op, args, kwargs, caption, role, style, label, branch, visible, unit, optional)
            if not computed:
                self._step[key] = step
        return step

    @property
    def steps(self) -> tuple[Step, ...]:
        """All steps in insertion (drawing) order."""
        self.complete()
        return tuple(self[k] for k in self._rec)

    def visible_steps(self) -> tuple[Step, ...]:
        """The steps that are drawn and numbered in the protocol, in order."""
        self.complete()
        return tuple(self[k] for k, r in self._rec.items() if r[8][4])

    def frames(self) -> list[list[Step]]:
        """The visible steps grouped by protocol number: a step with an empty caption is drawn with the
        numbered step before it (a link drawn with its position, a ground symbol with its pivot), except an
        annotation that shows a measurement (an angle mark with its value): it is drawn with the last
        measurement it refers to, so that the mark appears with the step that measures it — but never before
        the drawn steps it stands on (θ = 180°(K − 1)/(K + 1), step 1 of a design by K, had its mark drawn at
        step 1 about a vertex and lines not yet drawn: 21 players showed a floating arc). Unnumbered steps right
        before a numbered one that is drawn from them all go with it (the circles of "circles … meet at B′", the
        tick 1 of "divide the δ axis …", the end point vB of "the velocity vB …": 300-01 showed vB and the α
        mark on it one step before the vector, 20 cams the tick 1 with "Plot s(δ)"), unless the step before
        names one of them or draws the same kind of thing ("B1, B2 on ee" keeps B2; "lines … on either side").

        The grouping is remembered while the scene's records stay the same (a drawing, its protocol, its
        captions and its results' frames each ask for it); each call returns new lists."""
        self.complete()                         # a lean scene: its records only then
        rec = self._rec
        got = self.__dict__.get("_frames")
        if got is not None and got[0] is rec and got[1] == len(rec):
            return [list(g) for g in got[2]]
        out: list[list[Step]] = []
        where: dict[str, int] = {}
        visible = self.visible_steps()
        run: list[Step] = []                   # the unnumbered non-annotation steps since the last numbered one
        for s in visible:
            if s.caption[0] or s.branch is not None or not out:
                head = out[-1][0] if out else None
                ahead = bool(run) and all(r.key in rec[s.key][7] for r in run) and not any(
                    r.op is head.op or _names(head.caption[0], r.label) for r in run)
                if ahead:
                    del out[-1][-len(run):]
                out.append([s] + run if ahead else [s])
                for r in out[-1]:
                    where[r.key] = len(out) - 1
                run = []
                continue
            if s.role is Role.ANNOTATION:
                run = []
            else:
                run.append(s)
            at = len(out) - 1
            if s.role is Role.ANNOTATION:
                deps = rec[s.key][7]
                measured = [where[d] for d in deps if d in where and rec[d][8][1] is Role.MEASUREMENT]
                if measured:
                    at = max(measured + [where[d] for d in deps if d in where])
            out[at].append(s)
            where[s.key] = at
        self._frames = (rec, len(rec), tuple(tuple(g) for g in out))
        return out

    def available_at(self, keys: Iterable[str], default: int = 1) -> int:
        """The first frame (1-based) by which every step of ``keys`` is known: a visible step's own frame, an
        invisible one's the last frame among what it depends on (``default`` when nothing drawn produces it:
        a result the drawing never constructs, e.g. one computed from the givens alone)."""
        frame = {s.key: i for i, group in enumerate(self.frames(), 1) for s in group}
        rec = self._rec
        memo: dict[str, int] = {}

        def at(k: str) -> int:
            got = memo.get(k)
            if got is None:
                got = frame.get(k) or max((at(d) for d in rec[k][7]), default=0)
                memo[k] = got
            return got
        return max((at(k) for k in keys), default=0) or default

    def drawn_from(self, key: str) -> int | None:
        """The first frame (1-based) that draws a step computed from the value ``key`` (through values that are
        not drawn); None for a drawn step, or a value no drawn step is computed from. A result computed by a
        value the drawing constructs later shows with it, not before (200-07's α_max at step 2, its worst
        position drawn at step 17; 001-24's s at δ = 100° at step 1, laid off at step 15)."""
        rec = self._rec
        got = self.__dict__.get("_users")
        if got is None or got[0] is not rec or got[1] != len(rec):
            users: dict[str, list[str]] = {}
            for k, r in rec.items():
                for d in r[7]:
                    users.setdefault(d, []).append(k)
            frame = {s.key: i for i, group in enumerate(self.frames(), 1) for s in group}
            got = self._users = (rec, len(rec), users, frame)        # remembered as the frames are
        users, frame = got[2], got[3]
        if key in frame:
            return None
        seen, todo, found = {key}, [key], []
        while todo:
            for u in users.get(todo.pop(), ()):
                if u in seen:
                    continue
                seen.add(u)
                if u in frame:
                    found.append(frame[u])
                else:
                    todo.append(u)
        return min(found, default=None)

    def read_off(self, at: str | Ref, *keys: str | Ref) -> None:
        """Record that the values ``keys`` (answers) are read off the drawing at step ``at``, a step their values
        do not depend on: a result then shows no earlier than that step (:meth:`read_at`). The θ-circle designs
        compute AB = (AC2 − AC1)/2 from the candidate A; the drawing measures it at "Bisect N … at M: AB = NM,
        BC = AM", several steps later (001-10 showed AB, BC at step 23, measured at 27, and AD at 23, the frame
        drawn at 28). A step named here that the scene lacks (a drawing-only step of a lean scene) is passed over.

        >>> from geomcon.geometry import Point
        >>> sc = Scene()
        >>> A = sc.given("A", Point(0, 0), caption=("Pivot A", "铰链 A"))
        >>> D = sc.given("D", Point(3, 4), caption=("Pivot D", "铰链 D"))
        >>> ad = sc.add("AD", abs, 5.0, visible=False)
        >>> _ = sc.add("frame", repr, A, D, caption=("The frame AD", "机架 AD"))
        >>> sc.read_off("frame", ad)
        >>> sc.available_at(["AD"]), sc.read_at("AD"), sc.read_at("A")
        (1, 3, None)
        """
        at = at[0] if type(at) is Ref else at
        read = self.__dict__.setdefault("_read", {})
        for k in keys:
            k = k[0] if type(k) is Ref else k
            read[k] = (*read.get(k, ()), at)

    def read_at(self, key: str) -> int | None:
        """The frame (1-based) of the latest step at which the value ``key`` is read off the drawing
        (:meth:`read_off`); None when no step reads it off."""
        ats = [a for a in self.__dict__.get("_read", {}).get(key, ()) if a in self._rec]
        return self.available_at(ats) if ats else None

    def number(self, key: str) -> int:
        """1-based protocol number of a visible step (the number of the frame it is drawn in)."""
        for i, group in enumerate(self.frames(), 1):
            if any(s.key == key for s in group):
                return i
        raise KeyError(f"step '{key}' is not a visible step")

    def label_of(self, x: Any) -> str:
        """The printed label of a referenced point (its step label, else its key)."""
        key = x.key if isinstance(x, Ref) else str(x)
        if self._stale:
            self.complete()
        rec = self._rec.get(key)
        return (rec[8][3] or key) if rec else key

    def caption(self, key: str) -> tuple[str, str]:
        """The step's caption with its branch rule appended, in English and Chinese. A caption given as a
        :class:`Ref` is that step's value, an (en, zh) pair computed from the construction (a choice's caption
        naming the candidate chosen: computed when read, after a drawing of another solution fixed it). A
        step a lean or planned scene skipped is read after the scene completes itself."""
        if self._stale or (key not in self._rec and (self.lean or self._keep is not None)):
            self.complete()
        cap, branch = self._rec[key][8][0], self._rec[key][4]
        en, zh = self.value(cap[0]) if type(cap) is Ref else cap
        if branch is not None:
            ben, bzh = branch.describe(self.label_of)
            en = en_remark(en, ben) if en else ben
            zh = zh_remark(zh, bzh) if zh else bzh
        return en, zh

    def closure(self, keys: Iterable[str]) -> list[str]:
        """The keys needed to compute ``keys`` (themselves included), in evaluation order."""
        keys = tuple(keys)
        try:
            return order_of(self._rec, keys)
        except KeyError as exc:
            k = exc.args[0]
        # a step skipped here, or one a lean scene never added (drawing-only, under 'if sc.drawing'): a scene
        # that can complete itself does so; a full scene has no such step
        if k not in self._skip and (self._rebuild is None or not (self.lean or self._keep is not None)):
            raise KeyError(f"no step '{k}'")
        self._upgrade(k)
        return self.closure(keys)

    # ------------------------------------------------------------------ evaluating
    def value(self, key: str) -> Any:
        """The value of one step, computing what it needs (once)."""
        return self.evaluate((key,))[key]

    def evaluate(self, keys: Iterable[str]) -> dict[str, Any]:
        """Compute the requested steps and their dependencies; return ``{key: value}`` for ``keys``.

        Raises
        ------
        Unbuildable
            When a step fails; the message names the step, its caption and the numbers.
        """
        keys = tuple(keys)
        memo = self._memo
        tape = self._tape
        if self._pending is not None:
            self.settle()
        elif tape is not None and len(memo) == tape.n_inputs:       # a fresh replay: one compiled call
            run = tape.program(keys)
            if run is not None:
                try:
                    self._pending = run(memo)
                    return {k: memo[k] for k in keys}
                except Exception:            # evaluated step by step below, to report it as a step's failure
                    pass
        plan = _PLANS.get((self._sig, keys))
        if plan is None:
            plan = self.closure(keys)         # may complete the scene: cache under the signature it has now
            if len(_PLANS) >= _CACHE_MAX:
                _PLANS.clear()
            _PLANS[(self._sig, keys)] = plan
        if self._learn is not None:
            self._learn.update(plan)
        rec = self._rec
        for k in plan:
            if k not in memo:
                r = rec[k]
                if r[3] == _TOP and r[4] is None and not r[6]:      # the common case, inline
                    try:
                        memo[k] = r[0](*[memo[a[0]] if type(a) is Ref else a for a in r[1]], **r[2])
                    except GeomconError as exc:
                        raise Unbuildable(k, self.caption(k)[0], exc) from None
                else:
                    memo[k] = self._compute(k, r)
        return {k: memo[k] for k in keys}

    def _compute(self, key: str, rec: tuple) -> Any:
        op, args, kwargs, mode, branch, brefs, optional, _, _ = rec
        memo = self._memo
        try:
            if mode == _TOP:
                args = [memo[a[0]] if type(a) is Ref else a for a in args]
            elif mode == _DEEP:
                args = _resolve(args, memo)
                kwargs = {n: _resolve(v, memo) for n, v in kwargs.items()}
            if optional and mode != _PLAIN and _missing(rec[1], args, rec[2], kwargs):
                return None
            out = op(*args, **kwargs)
            if branch is not None:
                if not out:
                    if optional:
                        return None
                    raise NoIntersection(_no_meet_message(*args[:2]))
                out = branch.rule(out, *[memo[r[0]] if type(r) is Ref else r for r in brefs])
            return out
        except GeomconError as exc:
            raise Unbuildable(key, self.caption(key)[0], exc) from None

    def fix(self, key: str, value: Any) -> None:
        """Give step ``key`` the value ``value`` before anything is evaluated, instead of computing it: a
        drawing of another candidate of a construction fixes its choice step (``choice``) so.

        >>> sc = Scene()
        >>> i = sc.add("choice", int, 0)
        >>> sc.fix("choice", 2)
        >>> sc.value("choice")
        2

        Raises
        ------
        KeyError
            When there is no such step.
        ValueError
            When the step was evaluated already (to another value).
        """
        if key not in self._rec:
            raise KeyError(key)
        self.settle()
        if key in self._memo and self._memo[key] != value:
            raise ValueError(f"step '{key}' was evaluated already")
        self._memo[key] = value

    def is_evaluated(self, key: str) -> bool:
        """True when the step's value has been computed already."""
        self.settle()
        return key in self._memo

    @property
    def drawing(self) -> bool:
        """True when this scene may be drawn: recipes add drawing-only steps (links drawn as bars, ghost
        positions, angle marks, labels) under ``if sc.drawing:``, so that solving for answers does not even
        format their captions. A lean scene is not drawing; when a drawing asks for it, it is built again in
        full (:meth:`complete`)."""
        return not self.lean

    @property
    def stats(self) -> dict[str, int]:
        """``steps_total`` (every step of the full construction: a lean scene that can complete itself does so
        to count them, keeping its values) and ``steps_evaluated`` (computed so far)."""
        if self.lean and self._rebuild is not None:
            self.complete()
        self.settle()
        if self._stale:                      # a replayed tape that cannot complete itself
            return {"steps_total": sum(k[:1] != _TAPE for k in self._rec) + len(self._skip),
                    "steps_evaluated": sum(k[:1] != _TAPE for k in self._memo)}
        return {"steps_total": len(self._rec) + len(self._skip), "steps_evaluated": len(self._memo)}


def _missing(raw_args: tuple, args: Any, raw_kwargs: dict, kwargs: dict) -> bool:
    """True when a referenced value an optional step needs is None (a candidate that does not exist);
    a literal None argument (e.g. "default radius") does not count."""
    refs = [v for a, v in zip(raw_args, args) if type(a) is Ref]
    refs += [kwargs[n] for n, a in raw_kwargs.items() if type(a) is Ref]
    return any(v is None for v in refs)
