"""The typical mistakes of each recipe, declared as data: what a student plausibly drew instead, as a replay
of the recipe's own scene (never a formula typed by hand for the wrong answer).

A recipe's entry in :data:`MISTAKES` is a tuple of :class:`Mistake`; each has a ``code`` (the word grades.csv
shows), a ``kind`` saying how the scene is replayed, and one sentence in English and Chinese for the
feedback. Kinds:

``read``
    the answer is read off another step: ``answer`` read from step ``step`` (θ measured at D, i.e. ψ; the
    pitch curve's ρmin given for the actual profile's).
``op``
    step ``step`` computed by ``op`` instead, with the same arguments (K = (180° − θ)/(180° + θ); the larger
    transmission angle of the two crank-on-frame positions instead of the smaller); ``steps`` names several
    steps made the same wrong way in one replay (both θ-circles, both lines through A).
``rewire``
    step ``step`` made from step ``new`` where the recipe uses ``old`` (α taken at the other position).
``given``
    the whole scene replayed with givens changed: ``given`` maps a given's name to a function of its value
    (the cam turned the other way; the offset laid off on the other side).
``candidate``
    another candidate solution of the recipe (``Construction.solutions``) whose boolean answer ``flag`` differs
    from the textbook's choice (C1 taken as the extended position; A on the far arc of the θ-circle).

Shared mistakes need no entry: ``other_branch`` (every named branch rule the asked answers depend on, flipped
one at a time), ``swapped``, ``degrees_radians``, ``scale``, ``sign`` and ``rounding`` apply to every recipe
(:mod:`.diagnosis`). A teacher adds more in the spec (``[exercise.diagnose]``, :mod:`.expr`). A recipe that
declares nothing still gets the shared ones.

Examples
--------
>>> [m.code for m in mistakes_of("crank_rocker.extremes")]
['K_inverted', 'theta_psi', 'theta_psi', 'other_extreme_position']
>>> k_inverted(36.0)
0.6666666666666666
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Mapping


@dataclass(frozen=True)
class Mistake:
    """One declared mistake of a recipe (see the module for the kinds)."""

    code: str
    kind: str
    en: str
    zh: str
    answer: str = ""
    step: str = ""
    op: Callable[..., Any] | None = None
    old: str = ""
    new: str = ""
    given: Mapping[str, Callable[[Any], Any]] = field(default_factory=dict)
    flag: str = ""
    steps: tuple[str, ...] = ()

    def where(self) -> tuple[str, ...]:
        """The steps an ``op`` mistake replaces: ``steps``, else ``step``."""
        return self.steps or (self.step,)

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"mistake {self.code!r}: kind must be one of {', '.join(KINDS)}, got {self.kind!r}")


KINDS = ("read", "op", "rewire", "given", "candidate")


def k_inverted(theta: float) -> float:
    """K with the fraction upside down: (180° − θ)/(180° + θ)."""
    return (180.0 - theta) / (180.0 + theta)


def largest_of(*xs: float) -> float:
    """The larger value where the recipe takes the smaller."""
    return max(xs)


def _other_rotation(v: Any) -> Any:
    return "cw" if v in (None, "ccw") else "ccw"


def _negated(v: Any) -> Any:
    return -float(v) if v else v


def left_out(*_: Any) -> float:
    """A component left out of a polygon: its drawn length 0."""
    return 0.0


def coriolis_left_out(b2: Any, b3: Any, b2_: Any, *_: Any) -> Any:
    """The Coriolis component left out: k′ at b2′."""
    return b2_


def coriolis_reversed(b2: Any, b3: Any, b2_: Any, w3: float, mu_v: float, mu_a: float) -> Any:
    """The Coriolis component laid off against the sense of ω3."""
    from ..recipes.kinematics_common import coriolis_end
    k = coriolis_end(b2, b3, b2_, w3, mu_v, mu_a)
    return b2_ * 2.0 - k


def image_same_side(pole: Any, q: Any, C: Any, B: Any, D: Any) -> Any:
    """D's image laid off on the same side of the pole as B's (the arm's reversal about C forgotten)."""
    from ..recipes.slotter_kinematics import arm_image
    return pole * 2.0 - arm_image(pole, q, C, B, D)


def ratio_upside_down(P: Any, fixed1: Any, fixed2: Any) -> float:
    """An instant-centre ratio read the wrong way round: P34P13/P14P13 (ω1/ω3) where P14P13/P34P13 is asked."""
    from ..recipes.instant_centres import ratio_along
    return ratio_along(P, fixed2, fixed1)


def accel_times_omega(program: Any, h: float, omega: float, *rest: Any) -> tuple:
    """A cam follower's speeds with the acceleration taken as ω·s″ (ω not squared): :func:`speeds_at` or
    :func:`speed_maxima`'s result with every acceleration divided by ω."""
    from ..cam.kinematics import speed_maxima, speeds_at
    if rest and isinstance(rest[0], tuple):                         # speeds_at(program, h, ω, at, scale)
        v, a = speeds_at(program, h, omega, *rest)
        return v, tuple(x / omega for x in a)
    vm, dv, am, da = speed_maxima(program, h, omega, *rest)
    return vm, dv, am / omega, da


def rise_only(program: Any, h: float, omega: float, *rest: Any) -> tuple:
    """The maxima of the rise alone (the return's larger speeds not looked at)."""
    from ..cam.kinematics import speed_maxima
    from ..cam.program import Program
    return speed_maxima(Program(tuple(s for s in program.segments if s.kind != "return")), h, omega, *rest)


def rpm_as_rad_s(omega: Any) -> Any:
    """ω in rev/min used as if it were rad/s: the given ω (rad/s) times 60/(2π)."""
    return float(omega) * 30.0 / __import__("math").pi if omega else omega


def _over_omega(name: str) -> Callable[..., float]:
    """An op replaying the eccentric cam's step ``name`` (:mod:`geomcon.recipes.cam_eccentric_speeds`, whose
    last argument is ω) with its value divided by ω: an acceleration taken as ω·s″ (ω not squared)."""
    def op(*args: Any) -> float:
        from ..recipes import cam_eccentric_speeds
        return getattr(cam_eccentric_speeds, name)(*args) / args[-1]
    op.__name__ = f"{name}_times_omega"
    return op


def floor_added(rho_allow: float, floor: tuple) -> float:
    """A flat face's r0 = ρallow + min(s + s″) (the sign of the minimum lost)."""
    return rho_allow + floor[0]


_GUIDE_POLYGONS = (
    Mistake("coriolis_omitted", "op", "the Coriolis component 2ω3·vB3B2 left out", "漏掉了哥氏加速度 2ω3·vB3B2",
            step="k", op=coriolis_left_out),
    Mistake("coriolis_direction", "op", "the Coriolis component laid off against the sense of ω3",
            "哥氏加速度的方向画反了(未按 ω3 转向转 90°)", step="k", op=coriolis_reversed),
    Mistake("normal_omitted", "op", "the normal component ω3²·CB of B3 left out", "漏掉了 B3 点的法向加速度 ω3²·lCB",
            step="k_n3", op=left_out),
)
"""The guide bar's polygon mistakes (``guide_bar.kinematics`` and the slotter's guide part: the same steps)."""
_GUIDE_CRANK = Mistake("crank_reversed", "given", "vB2 laid off against the sense of ω", "vB2 的方向与 ω 转向相反",
                       given={"omega": _negated})


def theta_not_complement(theta: float, side: int) -> float:
    """The line from C1 drawn at θ to C1C2 where the θ-circle's construction draws it at 90° − θ (the
    circle then sees C1C2 under 90° − θ)."""
    return side * theta


def larger_frame_gamma(A: Any, D: Any, P1: Any, P2: Any) -> float:
    """γmin read at the crank-on-frame position with the larger transmission angle."""
    from ..recipes.common import frame_gammas
    return max(frame_gammas(A, D, P1, P2))


def _grashof_as_crank(L: Mapping[str, float], frame: str, x: str) -> tuple[str, bool]:
    """A student's rule: every chain that satisfies Grashof's condition is a crank-rocker (where the shortest
    link lies not looked at)."""
    from ..recipes.four_bar_link_ranges import grashof_kind
    k, gr = grashof_kind(L, frame, x)
    return (k if k == "immovable" else "crank_rocker" if gr else "double_rocker"), gr


def _longest_unchecked(L: Mapping[str, float], frame: str, x: str) -> tuple[str, bool]:
    """A student's rule: the case 'the unknown link is the longest' not written down, so its Grashof
    inequality is never checked (the chain typed by its shortest link alone there)."""
    from ..recipes.four_bar_link_ranges import by_shortest, grashof_kind
    k, gr = grashof_kind(L, frame, x)
    if k != "immovable" and not gr and L[x] >= max(v for n, v in L.items() if n != x):
        return by_shortest(L, frame), True
    return k, gr


def grashof_as_crank(*args: Any) -> tuple[float, ...]:
    """``four_bar.link_ranges``' boundaries when Grashof's condition alone is taken for a crank-rocker."""
    from ..recipes.four_bar_link_ranges import boundaries_of
    return boundaries_of(*args, kind=_grashof_as_crank)


def longest_case_forgotten(*args: Any) -> tuple[float, ...]:
    """``four_bar.link_ranges``' boundaries with the case 'the unknown is the longest link' left out."""
    from ..recipes.four_bar_link_ranges import boundaries_of
    return boundaries_of(*args, kind=_longest_unchecked)


def offset_added_twice(AB: float, e: float) -> float:
    """The second parallel through C drawn at AB + e as the first (the offset added on both sides: the
    extremes taken symmetric about AC). Only where the textbook's second parallel lies on the other side of A
    (e < AB); for e ≥ AB the student's drawing is not this replay, and the mistake is not offered."""
    if e >= AB:
        raise ValueError("e ≥ AB: both parallels lie on one side of A")
    return AB + e


def half_theta_turn(K: float, sign: float) -> float:
    """The line through A at θ/2 to AC where the stroke's crank angle 180° − θ puts it at 90° − θ/2."""
    from ..analytic.linkages import theta_from_k
    return sign * __import__("math").radians(theta_from_k(K) / 2.0)


def along_doubled(c: Any, b: Any, d: float) -> Any:
    """D laid off at twice the distance: the arm CD taken as the whole stroke S instead of S/2."""
    from ..geometry import point_along
    return point_along(c, b, 2.0 * d)


def not_halved(x: float, k: float) -> float:
    """θ/2 taken as θ: the extreme positions of a guide bar drawn at ±θ to CA (ψ = θ, each half θ/2)."""
    return x


def mirrored_about_first(v: Any) -> Any:
    """Angles turned the other way from the first: ψi → 2ψ1 − ψi (the inversion made in the wrong sense: the
    points turned through +(ψi − ψ1) where the method turns them through −(ψi − ψ1))."""
    if not isinstance(v, (list, tuple)) or not v:
        return v
    return type(v)(2.0 * float(v[0]) - float(x) for x in v)


_SPEEDS = (
    Mistake("omega_not_squared", "op", "the acceleration taken as ω·s″ (ω not squared)", "加速度算成了 ω·s″(ω 未平方)",
            step="speeds_at", op=accel_times_omega),
    Mistake("omega_not_squared", "op", "the acceleration taken as ω·s″ (ω not squared)", "加速度算成了 ω·s″(ω 未平方)",
            step="speed_maxima", op=accel_times_omega),
    Mistake("rise_only", "op", "the largest speed and acceleration of the rise only (the return's not compared)",
            "只求了推程的最大速度和加速度(未与回程比较)", step="speed_maxima", op=rise_only),
    Mistake("rpm_as_rad_s", "given", "the cam's speed in rev/min used as rad/s (not times 2π/60)",
            "把转速 (r/min) 当作角速度 (rad/s) 使用(未乘 2π/60)", given={"omega": rpm_as_rad_s}),
)
"""The follower-speed mistakes of the cam recipes with a given ω."""

_K_INV = Mistake("K_inverted", "op", "K computed upside down, (180° − θ)/(180° + θ)", "K 算成了 (180° − θ)/(180° + θ)",
                 step="K", op=k_inverted)
_PITCH = ("the pitch curve's value given for the actual profile (the roller radius not subtracted)",
          "给出的是理论廓线的值(未减去滚子半径)")
_THETA_LINE = ("the line from C1 drawn at θ to C1C2 instead of at 90° − θ (the circle then sees C1C2 under 90° − θ)",
               "过 C1 所作直线与 C1C2 成 θ 角而非 90° − θ(所得圆上对 C1C2 的张角为 90° − θ)")
_TURN = Mistake("inversion_direction", "given", "the follower turned with ω instead of −ω in the inversion",
                "反转时从动件按 ω 方向而非 −ω 方向转动", given={"rotation": _other_rotation})

MISTAKES: dict[str, tuple[Mistake, ...]] = {
    "crank_rocker.extremes": (
        _K_INV,
        Mistake("theta_psi", "read", "θ measured at D (the swing ψ) instead of at A", "在 D 处量角(摆角 ψ)当作了极位夹角 θ",
                answer="theta", step="psi"),
        Mistake("theta_psi", "read", "ψ measured at A (the angle θ) instead of at D", "在 A 处量角(极位夹角 θ)当作了摆角 ψ",
                answer="psi", step="theta"),
        Mistake("other_extreme_position", "op",
                "the transmission angle taken at the other crank-on-frame position (the larger one)",
                "传动角取在了另一个曲柄与机架共线的位置(较大者)", step="gamma_min", op=largest_of),
    ),
    "crank_slider.extremes": (
        _K_INV,
        Mistake("other_extreme_position", "rewire",
                "the pressure angle taken with the crank perpendicular to the guide on the near side",
                "压力角取在了曲柄垂直于导路的另一位置(靠近导路一侧)", step="alpha_max", old="alpha_3", new="alpha_4"),
        Mistake("other_extreme_position", "rewire",
                "the transmission angle taken with the crank perpendicular to the guide on the near side",
                "传动角取在了曲柄垂直于导路的另一位置(靠近导路一侧)", step="gamma_min", old="alpha_3", new="alpha_4"),
    ),
    "guide_bar.extremes": (
        _K_INV,
        Mistake("offset_forgotten", "given", "the offset e of the guide left out (sin(ψ/2) = AB/AC, H = 2·L·AB/AC)",
                "忽略了导路的偏距 e(按 sin(ψ/2) = AB/AC、H = 2·L·AB/AC 计算)", given={"e": lambda v: 0.0 if v else v}),
        Mistake("offset_symmetric", "op",
                "both parallels through C drawn at AB + e (the extremes taken symmetric about AC)",
                "两个极限位置的导路平行线都取在距 A 为 AB + e 处(误认为两极限位置关于 AC 对称)",
                step="r2", op=offset_added_twice),
    ),
    "four_bar.link_ranges": (
        Mistake("grashof_as_crank", "op",
                "every chain satisfying Grashof's condition taken for a crank-rocker (the shortest link's place ignored)",
                "把满足杆长条件的情况都当作曲柄摇杆机构(未看最短杆的位置)", step="boundaries", op=grashof_as_crank),
        Mistake("longest_case_forgotten", "op",
                "the case with the unknown link the longest not considered (its Grashof inequality never checked)",
                "漏掉了未知杆为最长杆的情况(未校核该情况的杆长条件)", step="boundaries", op=longest_case_forgotten),
    ),
    "crank_rocker.best_by_K": (
        Mistake("theta_circle_angle", "op", *_THETA_LINE, steps=("ncompl", "fcompl"), op=theta_not_complement),
        Mistake("other_extreme_position", "op",
                "γmin read at the other crank-on-frame position (the larger transmission angle)",
                "最小传动角取在了曲柄与机架共线的另一位置(较大者)", step="gamma_min", op=larger_frame_gamma),
    ),
    "slotter.design_by_K": (
        Mistake("stroke_angle", "op",
                "the lines through A drawn at θ/2 to AC (∠B1AB2 taken as θ instead of 180° − θ)",
                "过 A 的两直线与 AC 成 θ/2(把 ∠B1AB2 当作 θ,应为 180° − θ)", steps=("turn1", "turn2"), op=half_theta_turn),
        Mistake("theta_crank_angle", "read", "the crank angle of one stroke ∠B1AB2 = 180° − θ given for θ",
                "把一个行程的曲柄转角 ∠B1AB2 = 180° − θ 当作了极位夹角 θ", answer="theta", step="crank_angle"),
        Mistake("arm_full_stroke", "op", "the arm CD taken as the whole stroke S instead of S/2",
                "导杆臂长 CD 取成了整个行程 S(应为 S/2)", step="D1", op=along_doubled),
    ),
    "crank_slider.design_by_K": (
        Mistake("theta_circle_angle", "op", *_THETA_LINE, step="compl", op=theta_not_complement),
    ),
    "crank_slider.best_by_K": (
        Mistake("theta_circle_angle", "op", *_THETA_LINE, step="compl", op=theta_not_complement),
    ),
    "guide_bar.design_by_K": (
        Mistake("theta_not_halved", "op", "the extreme positions drawn at ±θ to CA instead of ±θ/2 (ψ = θ in all)",
                "导杆两极限位置与 CA 的夹角取成了 ±θ(应为 ±θ/2,ψ = θ)", step="half", op=not_halved),
    ),
    "shaper.design_by_K": (
        Mistake("theta_not_halved", "op", "the extreme positions drawn at ±θ to CA instead of ±θ/2 (ψ = θ in all)",
                "导杆两极限位置与 CA 的夹角取成了 ±θ(应为 ±θ/2,ψ = θ)", step="half", op=not_halved),
    ),
    "four_bar.function_generation": (
        Mistake("inversion_direction", "given", "the points turned the wrong way about D in the inversion (+Δψ for −Δψ)",
                "反转时各点绕 D 的转向弄反了(应转 −Δψ)", given={"psi": mirrored_about_first}),
    ),
    "rocker_slider.three_positions": (
        Mistake("inversion_direction", "given", "the points turned the wrong way about D in the inversion (+Δψ for −Δψ)",
                "反转时各点绕 D 的转向弄反了(应转 −Δψ)", given={"psi": mirrored_about_first}),
    ),
    "rocker_slider.two_positions": (
        Mistake("inversion_direction", "given", "the point turned the wrong way about D in the inversion (+Δψ for −Δψ)",
                "反转时该点绕 D 的转向弄反了(应转 −Δψ)", given={"psi": mirrored_about_first}),
    ),
    "crank_slider.instant_centres": (
        Mistake("ratio_inverted", "op", "ω1/ω2 given for ω2/ω1 (P24P12/P14P12)", "把 ω1/ω2 当作了 ω2/ω1",
                step="w2_w1", op=ratio_upside_down),
        Mistake("wrong_centre", "rewire", "vC/ω1 read at P24 (the rod's centre) instead of P13 (the crank's and the slider's)",
                "vC/ω1 取在了 P24(连杆的绝对瞬心)处,应取 P13(曲柄与滑块的相对瞬心)", step="vC_w1", old="P13", new="P24"),
    ),
    "crank_rocker.design_by_K": (
        Mistake("C1_C2", "candidate", "C1 and C2 exchanged (C1 taken as the extended position)",
                "C1 与 C2 弄反了(把拉直共线位置当作 C1)", flag="C1_folded"),
        Mistake("far_theta_circle", "candidate", "A taken on the far arc of the θ-circle",
                "A 取在了 θ 圆的另一段圆弧上", flag="A_near"),
        Mistake("theta_circle_angle", "op", *_THETA_LINE, steps=("ncompl", "fcompl"), op=theta_not_complement),
    ),
    "cam.translating": (
        Mistake("pitch_vs_actual", "read", *_PITCH, answer="rho_min_actual", step="rho_min_pitch"),
        _TURN,
        Mistake("offset_side", "given", "the offset laid off on the other side of the cam's centre",
                "偏距偏在了凸轮中心的另一侧", given={"e": _negated}),
        *_SPEEDS,
    ),
    "cam.oscillating": (
        Mistake("pitch_vs_actual", "read", *_PITCH, answer="rho_min_actual", step="rho_min_pitch"),
        Mistake("pitch_vs_actual", "read", *_PITCH, answer="profile_x", step="pitch_x"),
        Mistake("pitch_vs_actual", "read", *_PITCH, answer="profile_y", step="pitch_y"),
        _TURN,
        *_SPEEDS,
    ),
    "cam.base_radius": (
        Mistake("alpha_limit_only", "read", "the base circle of the pressure-angle limit alone (ρmin not checked)",
                "只按许用压力角确定基圆(未校核曲率半径)", answer="r0", step="r0_alpha"),
        Mistake("floor_sign", "op", "r0 = ρallow + min(s + s″): the minimum's sign lost",
                "r0 取成了 ρallow + min(s + s″)(最小值的符号弄错)", step="r0", op=floor_added),
        Mistake("centre_not_moved", "read", "the centre distance of the pressure-angle design kept after the base "
                "circle was grown for the curvature limit (oscillating)",
                "按曲率半径增大基圆后仍沿用按压力角设计的中心距 a(摆动从动件)", answer="a", step="a_alpha"),
        Mistake("centre_not_moved", "read", "the initial arm angle of the pressure-angle design kept after the base "
                "circle was grown for the curvature limit (oscillating)",
                "按曲率半径增大基圆后仍沿用按压力角设计的初始摆角 ψ0(摆动从动件)", answer="psi0", step="psi0_alpha"),
    ),
    "cam.eccentric": (
        Mistake("pitch_vs_actual", "read", "the base circle of the pitch curve given for the actual profile's",
                "给出的是理论廓线的基圆半径(未减去滚子半径)", answer="r0_actual", step="r0"),
        Mistake("omega_not_squared", "op", "the acceleration taken as ω·s″ (ω not squared)", "加速度算成了 ω·s″(ω 未平方)",
                step="a", op=_over_omega("guide_accel")),
        Mistake("omega_not_squared", "op", "the acceleration taken as ω·s″ (ω not squared)", "加速度算成了 ω·s″(ω 未平方)",
                step="a_max", op=_over_omega("guide_a_max")),
        Mistake("omega_not_squared", "op", "the angular acceleration taken as ω·ψ″ (ω not squared)",
                "角加速度算成了 ω·ψ″(ω 未平方)", step="epsilon2", op=_over_omega("arm_epsilon2")),
        Mistake("omega_not_squared", "op", "the angular acceleration taken as ω·ψ″ (ω not squared)",
                "角加速度算成了 ω·ψ″(ω 未平方)", step="epsilon2_max", op=_over_omega("arm_epsilon2_max")),
        Mistake("rpm_as_rad_s", "given", "the cam's speed in rev/min used as rad/s (not times 2π/60)",
                "把转速 (r/min) 当作角速度 (rad/s) 使用(未乘 2π/60)", given={"omega": rpm_as_rad_s}),
    ),
    "four_bar.kinematics": (
        Mistake("normal_omitted", "op", "the normal component ω2²·BC of C relative to B left out of the acceleration polygon",
                "加速度多边形中漏掉了 C 相对 B 的法向加速度 ω2²·lBC", step="k_n2", op=left_out),
        Mistake("normal_omitted", "op", "the normal component ω3²·CD of C left out of the acceleration polygon",
                "加速度多边形中漏掉了 C 点的法向加速度 ω3²·lCD", step="k_n3", op=left_out),
        Mistake("image_mirrored", "given", "the image triangle bce (b′c′e′) drawn turned the other way, a mirror image of BCE",
                "影像三角形 bce(b′c′e′)画反了(与 BCE 转向相反)", given={"angle_CBE": _negated}),
        Mistake("crank_reversed", "given", "vB laid off against the sense of ω", "vB 的方向与 ω 转向相反",
                given={"omega": _negated}),
    ),
    "crank_slider.kinematics": (
        Mistake("normal_omitted", "op", "the normal component ω2²·BC of C relative to B left out of the acceleration polygon",
                "加速度多边形中漏掉了 C 相对 B 的法向加速度 ω2²·lBC", step="k_n2", op=left_out),
        Mistake("crank_reversed", "given", "vB laid off against the sense of ω", "vB 的方向与 ω 转向相反",
                given={"omega": _negated}),
    ),
    "guide_bar.kinematics": _GUIDE_POLYGONS + (_GUIDE_CRANK,),
    "slotter.kinematics": _GUIDE_POLYGONS + (
        Mistake("normal_omitted", "op", "the normal component ω4²·DE of E relative to D left out",
                "漏掉了 E 相对 D 的法向加速度 ω4²·lDE", step="k_n4", op=left_out),
        Mistake("image_same_side", "op", "D's image d laid off on b3's side of p (D lies beyond C, opposite B)",
                "D 的速度影像 d 取在了 b3 一侧(D 与 B 分居 C 两侧)", step="d", op=image_same_side),
        Mistake("image_same_side", "op", "D's image d′ laid off on b3′'s side of p′ (D lies beyond C, opposite B)",
                "D 的加速度影像 d′ 取在了 b3′ 一侧(D 与 B 分居 C 两侧)", step="d2", op=image_same_side),
        _GUIDE_CRANK,
    ),
    "four_bar.analysis": (
        _K_INV,
        Mistake("theta_psi", "read", "θ measured at the rocker's pivot (the swing ψ) instead of at the crank's",
                "在摇杆转动中心处量角(摆角 ψ)当作了极位夹角 θ", answer="theta", step="psi"),
        Mistake("pressure_vs_transmission", "read", "the transmission angle γ given for the pressure angle α = 90° − γ",
                "把传动角 γ 当作了压力角 α = 90° − γ", answer="alpha", step="gamma"),
        Mistake("other_extreme_position", "op",
                "γmin taken at the other driver-on-frame position (the larger transmission angle)",
                "最小传动角取在了主动件与机架共线的另一位置(较大者)", step="gamma_min", op=largest_of),
    ),
    "rotating_guide_bar.extremes": (
        Mistake("slow_quick", "read", "the return stroke's crank angle given for the working stroke's",
                "把空回行程的曲柄转角当作了工作行程的", answer="phi_slow", step="phi_quick"),
        Mistake("K_inverted", "op", "K computed upside down, φquick/φslow", "K 算成了 φquick/φslow",
                step="K", op=lambda slow, quick: quick / slow),
    ),
    "four_bar.instant_centres": (
        Mistake("ratio_inverted", "op", "ω1/ω3 given for ω3/ω1 (P34P13/P14P13)", "把 ω1/ω3 当作了 ω3/ω1",
                step="w3_w1", op=ratio_upside_down),
        Mistake("ratio_inverted", "read", "ω3/ω1 given for the transmission ratio i13 = ω1/ω3", "把 ω3/ω1 当作了传动比 i13",
                answer="i13", step="w3_w1"),
        Mistake("ratio_inverted", "op", "ω1/ω2 given for ω2/ω1 (P24P12/P14P12)", "把 ω1/ω2 当作了 ω2/ω1",
                step="w2_w1", op=ratio_upside_down),
    ),
}
"""Recipe name → its declared mistakes (recipes of later issues add their entries here)."""

NONE_DECLARED: dict[str, str] = {
    "four_bar.three_positions": (
        "A and D are the circumcentres of B1B2B3 and C1C2C3: any two of the three perpendicular bisectors give the "
        "same point, and no step has a branch, so a wrong pivot is a drafting error or A and D exchanged (swapped)"),
    "four_bar.three_positions_fixed_pivots": (
        "the inversion maps D into the coupler's first position by each position's rigid motion; turned the wrong "
        "way it is not the design of any changed givens, so it cannot be replayed as a given; a wrong C1 is a "
        "drafting error or one of the shared codes (swapped, scale, sign)"),
}
"""Recipes that declare no mistake of their own, and why (the shared codes still apply to them)."""


def mistakes_of(recipe: str) -> tuple[Mistake, ...]:
    """The declared mistakes of ``recipe`` (none for a recipe without an entry)."""
    return MISTAKES.get(recipe, ())


__all__ = ["KINDS", "MISTAKES", "NONE_DECLARED", "Mistake", "mirrored_about_first", "not_halved", "accel_times_omega", "along_doubled", "grashof_as_crank", "half_theta_turn",
           "larger_frame_gamma", "longest_case_forgotten", "offset_added_twice", "theta_not_complement", "floor_added", "rise_only", "rpm_as_rad_s", "coriolis_left_out", "coriolis_reversed", "k_inverted", "largest_of",
           "left_out", "mistakes_of", "ratio_upside_down"]
