"""A Moodle question bank (Moodle XML) from a worksheet key: one category per exercise, one question per
student's variant in it (Moodle's "random question from category" then gives each student one variant).

A single asked answer is a ``numerical`` question; several make a ``cloze`` question (embedded
``{points:NUMERICAL:…}`` answers). Each has the variant's statement, its givens figure (the construction's
first frames, up to the first construction line: the given points and lines, no answer) embedded as a base64
SVG file referred to as ``@@PLUGINFILE@@/<name>``, the right value with the key's tolerance at 100 %, and each
diagnosed mistake's value (:mod:`.diagnosis`) as a wrong answer with its feedback, at 0 % or at the partial
fraction of :data:`~.credit.PARTIAL`; units (mm and cm, ° and deg) are accepted and optional.
"""
from __future__ import annotations

import base64
from html import escape
from typing import Iterable
from xml.sax.saxutils import escape as xml_escape

from ..scene.step import Role
from ..solve import Solution
from ..worksheet.solving import solve_given
from .credit import PARTIAL
from .diagnosis import Prepared, prepare
from .keyfile import Answer, ExerciseKey, Key
from .tables import num

MAX_WRONG = 12
"""Wrong answers listed per asked answer (the nearest replays first, as :mod:`.diagnosis` orders them)."""
_UNITS = {"mm": (("mm", "1"), ("cm", "0.1")), "deg": (("°", "1"), ("deg", "1"))}


def _cdata(html: str) -> str:
    return "<![CDATA[" + html.replace("]]>", "]]]]><![CDATA[>") + "]]>"


def givens_svg(ex: ExerciseKey, sol: Solution | None = None) -> str:
    """The variant's givens figure: the construction's leading frames that hold only givens, annotations and
    measurements not asked (up to its first construction line or result), drawn in the full construction's view
    (room to construct), without the protocol, the results or the warnings: no answer anywhere in the file.
    ``sol`` is the variant's solution when it is at hand (the replayable variant of :func:`.diagnosis.prepare`
    solved it already: the same givens, so the same figure), else it is solved here."""
    from ..render import render_svg
    from ..render.svg import model_extent

    if sol is None:
        sol = solve_given(ex.recipe, ex.given)
    asked = {sol.construction.answers.get(a.ref.name) for a in ex.answers}
    sc = sol.drawing_scene
    k = 0
    drop = set()
    for steps in sc.frames():
        if any(s.role in (Role.CONSTRUCTION, Role.RESULT) or s.key in asked for s in steps):
            break
        k += 1
        if not any(s.role is Role.GIVEN for s in steps):
            drop.add(str(k))        # a measured angle's mark sits where the construction will put its vertex
    svg = render_svg(sc, upto=max(k, 1), viewbox=model_extent(sc), title=sol.title(), protocol=False)
    return _without_frames(svg, drop) if drop else svg


def _without_frames(svg: str, frames: set[str]) -> str:
    """``svg`` without the step groups of ``frames`` (``data-step``)."""
    import xml.etree.ElementTree as ET

    ET.register_namespace("", "http://www.w3.org/2000/svg")
    ET.register_namespace("xlink", "http://www.w3.org/1999/xlink")
    root = ET.fromstring(svg)
    for parent in list(root.iter()):
        for child in list(parent):
            if child.get("data-step") in frames:
                parent.remove(child)
    return ET.tostring(root, encoding="unicode")


def _alts(p, a: Answer) -> list:
    seen, out = set(), []
    for alt in p.alts.get(a.column, ()):
        if isinstance(alt.value, tuple):
            continue
        v = num(alt.value, max(abs(a.expected), 1.0))
        if v in seen:
            continue
        seen.add(v)
        out.append((alt, v))
    return out[:MAX_WRONG]


def _cloze_escape(text: str) -> str:
    for ch in "\\}#~/\"{":
        text = text.replace(ch, "\\" + ch)
    return text


def _numerical(a: Answer, p) -> list[str]:
    scale = max(abs(a.expected), 1.0)
    out = [f'<answer fraction="100" format="moodle_auto_format"><text>{num(a.expected, scale)}</text>'
           f'<feedback format="html"><text>Correct.</text></feedback><tolerance>{num(a.tol)}</tolerance></answer>']
    for alt, v in _alts(p, a):
        frac = num(100 * PARTIAL.get(alt.code, 0.0))
        out.append(f'<answer fraction="{frac}" format="moodle_auto_format"><text>{v}</text><feedback format="html">'
                   f"<text>{xml_escape(f'{alt.code}: {alt.en} / {alt.zh}')}</text></feedback>"
                   f"<tolerance>{num(alt.tol, scale)}</tolerance></answer>")
    units = _UNITS.get(a.unit, ())
    out.append("<unitgradingtype>0</unitgradingtype><unitpenalty>0.1000000</unitpenalty><showunits>3</showunits>"
               "<unitsleft>0</unitsleft>")
    if units:
        out.append("<units>" + "".join(f"<unit><multiplier>{m}</multiplier><unit_name>{xml_escape(u)}</unit_name></unit>"
                                       for u, m in units) + "</units>")
    return out


def _cloze_field(a: Answer, p) -> str:
    scale = max(abs(a.expected), 1.0)
    parts = [f"={num(a.expected, scale)}:{num(a.tol)}#Correct."]
    for alt, v in _alts(p, a):
        parts.append(f"%{num(100 * PARTIAL.get(alt.code, 0.0))}%{v}:{num(alt.tol, scale)}#"
                     + _cloze_escape(f"{alt.code}: {alt.en} / {alt.zh}"))
    return "{" + num(a.points) + ":NUMERICAL:" + "~".join(parts) + "}"


def _question(key: Key, sid: str, variant: str, ex: ExerciseKey, figure: bool, p: Prepared) -> str:
    name = f"{key.heading()} — {ex.n} — {variant or sid}"
    fname = f"ex{ex.n}-{(variant or sid).replace('/', '_')}.svg"
    text = f"<p>{escape(ex.statement)}</p>"
    files = ""
    if figure:
        svg = givens_svg(ex, p.variant.solution if p.variant is not None else None)
        text += f'<p><img src="@@PLUGINFILE@@/{escape(fname)}" alt="givens" /></p>'
        files = f'<file name="{xml_escape(fname)}" path="/" encoding="base64">{base64.b64encode(svg.encode()).decode()}</file>'
    answered = [a for a in ex.answers if not isinstance(a.expected, tuple)]
    head = f"<name><text>{xml_escape(name)}</text></name>"
    if len(answered) == 1:
        a = answered[0]
        body = [f'<question type="numerical">{head}',
                f'<questiontext format="html"><text>{_cdata(text)}</text>{files}</questiontext>',
                '<generalfeedback format="html"><text></text></generalfeedback>',
                f"<defaultgrade>{num(a.points)}</defaultgrade><penalty>0.3333333</penalty><hidden>0</hidden>",
                *_numerical(a, p), "</question>"]
        return "\n".join(body)
    fields = "".join(f"<p>{escape(a.ref.text)} = {_cloze_field(a, p)} {escape(_unit(a))}</p>" for a in answered)
    return "\n".join([f'<question type="cloze">{head}',
                      f'<questiontext format="html"><text>{_cdata(text + fields)}</text>{files}</questiontext>',
                      '<generalfeedback format="html"><text></text></generalfeedback>',
                      "<penalty>0.3333333</penalty><hidden>0</hidden>", "</question>"])


def _unit(a: Answer) -> str:
    return {"mm": "mm", "deg": "°"}.get(a.unit, "")


def moodle_xml(key: Key, *, figures: bool = True, ids: Iterable[str] | None = None,
               cache: dict[tuple[str, int], Prepared] | None = None) -> str:
    """The question bank's text (see the module). Each variant's alternatives are computed once, keyed by the
    variant code and exercise as :func:`geomcon.grading.grade` keys them (in ``cache`` when one is given: the
    grading of the same key may have computed them already)."""
    prepared = cache if cache is not None else {}
    chosen = list(ids) if ids is not None else list(key.students)
    numbers = sorted({ex.n for s in key.students.values() for ex in s.exercises})
    out = ['<?xml version="1.0" encoding="UTF-8"?>', "<quiz>"]
    title = key.heading().replace("/", "-") or "geomcon"
    for n in numbers:
        out.append(f'<question type="category"><category><text>{xml_escape(f"$course$/top/{title}/Exercise {n}")}'
                   "</text></category><info format=\"html\"><text></text></info></question>")
        seen = set()
        for sid in chosen:
            s = key.students[sid]
            for ex in s.exercises:
                if ex.n != n:
                    continue
                code = s.variant.split("-")[n - 1] if s.variant.count("-") >= n - 1 and s.variant else sid
                if code in seen:
                    continue
                seen.add(code)
                k = (s.variant or sid, n)
                if k not in prepared:
                    prepared[k] = prepare(ex)
                out.append(_question(key, sid, f"{n}-{code}", ex, figures, prepared[k]))
    out.append("</quiz>")
    return "\n".join(out) + "\n"


__all__ = ["MAX_WRONG", "givens_svg", "moodle_xml"]
