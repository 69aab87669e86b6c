"""Results as a textbook prints them: one table from an answer's name to its symbol, its English and Chinese
words and its unit, and the result lines of a drawing built from it.

A number reads ``θ = 12.506°``, a yes/no answer ``C1 folded: yes``; the remark in brackets says what agreed
with what (``= analytic``: the construction equals the independent analytic twin) and how the printed answer
of the textbook deviates. Chinese text uses full-width punctuation （，：；（））.

Examples
--------
>>> result_line("theta", 12.50559, "deg", twin=True, lang="en")
'θ = 12.506° (= analytic)'
>>> result_line("theta", 12.50559, "deg", twin=True, lang="zh")
'极位夹角 θ = 12.506°（与解析解一致）'
>>> result_line("C1_folded", True, "", twin=True, lang="en")
'C1 folded: yes (= analytic)'
>>> result_line("branch_ok", False, "bool", twin=True, lang="both")
'one assembly branch: no (= analytic)  在同一装配分支上：否'
>>> result_line("gamma_min", 40.1, "deg", twin=False, lang="en")
'γmin = 40.100° (≠ analytic)'
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, Mapping, Sequence


@dataclass(frozen=True)
class AnswerName:
    """How a result is printed: ``symbol`` (a number: ``symbol = value unit``; empty for a yes/no answer),
    ``en`` and ``zh`` words (a yes/no answer: the statement it answers)."""

    symbol: str
    en: str
    zh: str


def _n(symbol: str, en: str, zh: str) -> AnswerName:
    return AnswerName(symbol, en, zh)


def _b(en: str, zh: str) -> AnswerName:
    return AnswerName("", en, zh)


NAMES: dict[str, AnswerName] = {
    # cams
    "r0": _n("r0", "base circle radius", "基圆半径"),
    "e": _n("e", "offset", "偏距"),
    "s0": _n("s0", "height of B0 above O", "B0 高于 O"),
    "rho_min_pitch": _n("ρmin", "pitch curve, least radius of curvature", "理论廓线最小曲率半径"),
    "rr_max": _n("rr,max", "largest roller radius", "滚子半径上限"),
    "a": _n("a", "centre distance OA0", "中心距"),
    "psi0": _n("ψ0", "initial angle of the arm", "摆杆初始角"),
    "r0_actual": _n("r0′", "base circle of the actual profile", "实际廓线基圆半径"),
    "h": _n("h", "stroke", "行程"),
    "psi_max": _n("ψmax", "angular stroke", "最大摆角"),
    "rise_angle": _n("δ0", "rise angle", "推程运动角"),
    "return_angle": _n("δ0′", "return angle", "回程运动角"),
    "alpha_max_rise": _n("αmax", "rise, largest pressure angle", "推程最大压力角"),
    "delta_alpha_max_rise": _n("δ(αmax)", "rise, cam angle of αmax", "推程 αmax 处凸轮转角"),
    "alpha_min_rise": _n("αmin", "rise, smallest pressure angle", "推程最小压力角"),
    "alpha_max_return": _n("α′max", "return, largest pressure angle", "回程最大压力角"),
    "delta_alpha_max_return": _n("δ(α′max)", "return, cam angle of α′max", "回程 α′max 处凸轮转角"),
    "alpha_max": _n("αmax", "largest pressure angle", "最大压力角"),
    "offset_correct": _b("offset on the correct side", "偏置方位正确"),
    "delta": _n("δ", "cam angle", "凸轮转角"),
    "s": _n("s", "displacement", "位移"),
    "psi": _n("ψ", "swing of the arm", "摆角"),
    "alpha": _n("α", "pressure angle", "压力角"),
    "v": _n("v", "follower velocity", "从动件速度"),
    "rho_min_actual": _n("ρa,min", "actual profile, least radius of curvature", "实际廓线最小曲率半径"),
    "undercut": _b("undercut (motion distorted)", "运动失真（根切）"),
    "pitch_x": _n("xp", "pitch points", "理论廓线点"),
    "pitch_y": _n("yp", "pitch points", "理论廓线点"),
    "profile_x": _n("xa", "profile points", "实际廓线点"),
    "profile_y": _n("ya", "profile points", "实际廓线点"),
    "convex": _b("profile convex", "廓线外凸"),
    "face_min": _n("lmin", "contact along the face, nearest", "接触点最近位置"),
    "face_max": _n("lmax", "contact along the face, farthest", "接触点最远位置"),
    "face_length": _n("lface", "face length swept", "平底工作长度"),
    "face_contact": _n("l", "contact along the face", "接触点位置"),
    "face_width_left": _n("lL", "face width left of the axis", "平底左侧宽度"),
    "face_width_right": _n("lR", "face width right of the axis", "平底右侧宽度"),
    "face_width": _n("L", "face width", "平底宽度"),
    # linkages
    "AB": _n("AB", "crank", "曲柄"),
    "BC": _n("BC", "coupler", "连杆"),
    "AD": _n("AD", "frame", "机架"),
    "CD": _n("CD", "rocker", "摇杆"),
    "AC": _n("AC", "frame", "机架"),
    "gamma_min": _n("γmin", "smallest transmission angle", "最小传动角"),
    "theta": _n("θ", "crank angle between extreme positions", "极位夹角"),
    "K": _n("K", "time-ratio coefficient", "行程速比系数"),
    "C1_folded": _b("C1 folded", "C1 为重叠共线位置"),
    "A_near": _b("A on D's side of C1C2", "A 与 D 在 C1C2 同侧"),
    "DE": _n("DE", "output arm", "输出摆杆"),
    "gamma_1": _n("γ1", "transmission angle, crank along AD", "曲柄与 AD 重合时的传动角"),
    "gamma_2": _n("γ2", "transmission angle, crank along DA extended", "曲柄与 DA 延长线重合时的传动角"),
    # the angle the crank line makes with the frame, not the position itself (001-08 glossed ∠C1AD "重叠共线极限位置")
    "angle_C1AD": _n("∠C1AD", "crank line AC1 to the frame, folded extreme position", "重叠共线位置 AC1 与机架的夹角"),
    "angle_C2AD": _n("∠C2AD", "crank line AC2 to the frame, extended extreme position", "拉直共线位置 AC2 与机架的夹角"),
    "gamma_w_min": _n("γw,min", "working stroke, smallest transmission angle", "工作行程最小传动角"),
    "AC1": _n("AC1", "A to the folded extreme position", "A 至重叠共线位置"),
    "AC2": _n("AC2", "A to the extended extreme position", "A 至拉直共线位置"),
    "H": _n("H", "stroke C1C2", "行程"),
    "gamma_min_fast": _n("γq,min", "fast stroke, smallest transmission angle", "空回行程最小传动角"),
    "gamma_min_slow": _n("γw,min", "slow stroke, smallest transmission angle", "工作行程最小传动角"),
    "C1": _n("C1", "hinge position 1", "铰链位置 1"),
    "beta": _n("β", "angle of DC from DE, counter-clockwise", "自 DE 逆时针量到 DC 的角"),
    "grashof": _b("Grashof condition met", "满足杆长条件"),
    "crank": _b("AB is a crank", "AB 为曲柄"),
    "branch_ok": _b("one assembly branch", "在同一装配分支上"),
    "order_ok": _b("positions reached in order", "按顺序到达各位置"),
    "sens_C1": _n("ΔC1/0.1°", "per 0.1° of error", "每 0.1° 误差的偏移"),
    "sens_C1_mm": _n("ΔC1/0.1 mm", "per 0.1 mm of error", "每 0.1 mm 误差的偏移"),
    "A": _n("A", "fixed pivot", "固定铰链"),
    # linkage analysis (issue 14)
    "type": _n("type", "type of the chain", "机构类型"),
    "A_full": _b("A turns fully", "A 为周转副"),
    "B_full": _b("B turns fully", "B 为周转副"),
    "C_full": _b("C turns fully", "C 为周转副"),
    "D_full": _b("D turns fully", "D 为周转副"),
    "input_crank": _b("the link at the first pivot is a crank", "第一固定铰链处的连架杆为曲柄"),
    "output_crank": _b("CD turns fully", "CD 能整周转动"),
    "dead_points": _b("dead points in the motion", "存在死点"),
    "gamma": _n("γ", "transmission angle at φ", "φ 位置的传动角"),
    "crank_rocker": _n("crank-rocker", "lengths for a crank-rocker", "曲柄摇杆机构的杆长范围"),
    "double_crank": _n("double-crank", "lengths for a double-crank", "双曲柄机构的杆长范围"),
    "double_rocker": _n("double-rocker", "lengths for a double-rocker", "双摇杆机构的杆长范围"),
    "immovable": _n("immovable", "lengths for which the chain cannot move", "不能运动的杆长范围"),
    "grashof_ranges": _n("Grashof", "lengths for which s + l ≤ p + q", "满足杆长条件的杆长范围"),
    "boundaries": _n("boundaries", "lengths where the type changes", "类型改变处的杆长"),
    "phi_slow": _n("φslow", "crank angle of the working stroke", "工作行程曲柄转角"),
    "phi_quick": _n("φquick", "crank angle of the return stroke", "空回行程曲柄转角"),
    "S": _n("S", "stroke of the ram", "滑枕行程"),
    "B1B2": _n("B1B2", "where B's path crosses ee", "B 点轨迹与导路的交点距离"),
    "D": _n("D", "fixed pivot", "固定铰链"),
    "grashof_margin": _n("(p + q) − (s + l)", "Grashof margin", "杆长条件余量"),
    "gamma_min_work": _n("γw,min", "working range, smallest transmission angle", "工作范围最小传动角"),
    "phi": _n("φ", "directions of AB", "AB 的方向角"),
    "sens_A": _n("ΔA", "per 0.1 mm of error", "每 0.1 mm 误差的偏移"),
    "sens_D": _n("ΔD", "per 0.1 mm of error", "每 0.1 mm 误差的偏移"),
    "sens_C": _n("ΔC1", "per 0.1 mm of error", "每 0.1 mm 误差的偏移"),
    "F1": _n("F1", "hinge position 1", "铰链位置 1"),
    "DF": _n("DF", "rocker arm", "摇杆"),
    "EF": _n("EF", "connecting rod", "连杆"),
    "sens_F1": _n("ΔF1/0.1°", "per 0.1° of error", "每 0.1° 误差的偏移"),
    "sens_F1_mm": _n("ΔF1/0.1 mm", "per 0.1 mm of error", "每 0.1 mm 误差的偏移"),
    "E1": _n("E1", "pin position 1", "销位置 1"),
    "s_E1": _n("sE1", "pin along the guide", "销沿导路的位置"),
    "sens_E1": _n("ΔE1/0.1°", "per 0.1° of error", "每 0.1° 误差的偏移"),
    "sens_E1_mm": _n("ΔE1/0.1 mm", "per 0.1 mm of error", "每 0.1 mm 误差的偏移"),
    "deviation": _n("f", "largest distance of D from the guide", "D 偏离导路的最大距离"),
    # kinematics (velocity and acceleration polygons)
    "omega2": _n("ω2", "angular velocity of BC", "连杆角速度"),
    "epsilon2": _n("ε2", "angular acceleration of BC", "连杆角加速度"),
    "omega3": _n("ω3", "angular velocity of link 3 (rocker or guide)", "构件 3（摇杆或导杆）的角速度"),
    "epsilon3": _n("ε3", "angular acceleration of link 3 (rocker or guide)", "构件 3（摇杆或导杆）的角加速度"),
    "vC": _n("vC", "velocity of C", "C 点速度"),
    "aC": _n("aC", "acceleration of C", "C 点加速度"),
    "vE": _n("vE", "velocity of E", "E 点速度"),
    "aE": _n("aE", "acceleration of E", "E 点加速度"),
    "mu_v": _n("μv", "velocity polygon scale", "速度比例尺"),
    "mu_a": _n("μa", "acceleration polygon scale", "加速度比例尺"),
    "v_slip": _n("vB2B3", "velocity of B2 along the guide", "B2 相对导杆的速度"),
    "a_slip": _n("aʳB2B3", "relative acceleration of B2 along the guide", "B2 相对导杆的加速度"),
    "a_coriolis": _n("aᵏB2B3", "Coriolis acceleration", "科氏加速度"),
    "vB3": _n("vB3", "velocity of the guide's point under the block", "导杆上与滑块重合点的速度"),
    "vD": _n("vD", "velocity of D", "D 点速度"),
    "aD": _n("aD", "acceleration of D", "D 点加速度"),
    "omega4": _n("ω4", "angular velocity of link 4 (coupler DE)", "构件 4（连杆 DE）的角速度"),
    "epsilon4": _n("ε4", "angular acceleration of link 4 (coupler DE)", "构件 4（连杆 DE）的角加速度"),
    # instant centres
    "P13": _n("P13", "instant centre of crank and rocker", "曲柄与摇杆的瞬心"),
    "P24": _n("P24", "instant centre of coupler and frame", "连杆与机架的瞬心"),
    "w3_w1": _n("ω3/ω1", "from P13", "由 P13 求得"),
    "w2_w1": _n("ω2/ω1", "from P24", "由 P24 求得"),
    "i13": _n("i13", "transmission ratio ω1/ω3", "传动比 ω1/ω3"),
    "vC_w1": _n("vC/ω1", "slider velocity per unit crank speed", "滑块速度与曲柄角速度之比"),
    # cams: the follower's speeds (issue 14), the base circle's limits
    "v_max": _n("vmax", "largest follower speed", "从动件最大速度"),
    "a_max": _n("amax", "largest follower acceleration", "从动件最大加速度"),
    "omega2_max": _n("ω2,max", "largest angular speed of the arm", "摆杆最大角速度"),
    "epsilon2_max": _n("ε2,max", "largest angular acceleration of the arm", "摆杆最大角加速度"),
    "r0_alpha": _n("r0,α", "base circle of the pressure-angle limit alone", "仅按许用压力角的基圆半径"),
    "r0_rho": _n("r0,ρ", "base circle of the curvature limit", "按曲率半径限制的基圆半径"),
    "rho_min_profile": _n("ρa,min", "smallest radius of curvature of the profile", "实际廓线最小曲率半径"),
}
"""Every answer's printed name. An answer missing here prints its name with ``_`` as a space."""

RECIPE_NAMES: dict[tuple[str, str], AnswerName] = {
    # the synthesis recipes' output_crank is CD's; the analysis's is the link at the frame's second pivot
    # (001-03c, frame CD, printed "CD turns fully" for its frame)
    # the sign of a designed offset says its side (200-11 printed e = -5.657 mm with no side): the words say how
    ("cam.base_radius", "e"): _n("e", "offset (> 0: the follower's axis right of O)", "偏距（正值：导路在 O 右侧）"),
    ("rocker_slider.three_positions", "beta"): _n("β", "angle of DF from DK, counter-clockwise",
                                                  "自 DK 逆时针量到 DF 的角"),
    ("four_bar.analysis", "output_crank"): _b("the link at the second pivot is a crank", "第二固定铰链处的连架杆为曲柄"),
    ("cam.translating", "v"): _n("v", "follower velocity at the cam angles asked", "从动件速度"),
    ("cam.translating", "a"): _n("a", "follower acceleration at the cam angles asked", "从动件加速度"),
    # link 3 named as the mechanism has it (400-01 printed "构件 3（摇杆或导杆）的角速度" for a four-bar's rocker)
    ("four_bar.kinematics", "omega3"): _n("ω3", "angular velocity of the rocker CD", "摇杆 CD 的角速度"),
    ("four_bar.kinematics", "epsilon3"): _n("ε3", "angular acceleration of the rocker CD", "摇杆 CD 的角加速度"),
    ("guide_bar.kinematics", "omega3"): _n("ω3", "angular velocity of the guide bar", "导杆角速度"),
    ("guide_bar.kinematics", "epsilon3"): _n("ε3", "angular acceleration of the guide bar", "导杆角加速度"),
    ("slotter.kinematics", "omega3"): _n("ω3", "angular velocity of the guide bar", "导杆角速度"),
    ("slotter.kinematics", "epsilon3"): _n("ε3", "angular acceleration of the guide bar", "导杆角加速度"),
    ("cam.oscillating", "omega2"): _n("ω2", "angular velocity of the arm", "摆杆角速度"),
    ("cam.oscillating", "epsilon2"): _n("ε2", "angular acceleration of the arm", "摆杆角加速度"),
    ("cam.eccentric", "a"): _n("a", "follower acceleration", "从动件加速度"),
    ("cam.eccentric", "alpha_max"): _n("αmax,turn", "largest pressure angle of the turn", "全周最大压力角"),
    ("cam.eccentric", "omega2"): _n("ω2", "angular velocity of the arm", "摆杆角速度"),
    ("cam.eccentric", "epsilon2"): _n("ε2", "angular acceleration of the arm", "摆杆角加速度"),
    # a guide bar is no rocker, and the link from it to the ram no output arm (001-19 printed "CD … 摇杆" for the
    # arm of a fully rotating guide bar and "DE … 输出摆杆" for the coupler to the slide)
    ("slotter.design_by_K", "CD"): _n("CD", "arm of the rotating guide bar", "转动导杆的臂长"),
    ("slotter.design_by_K", "DE"): _n("DE", "coupler to the slide", "连杆"),
    ("shaper.design_by_K", "CD"): _n("CD", "guide bar, C to D", "导杆"),
    ("shaper.design_by_K", "DE"): _n("DE", "coupler to the ram", "连杆"),
    # h is where the ram's guide lies, not the stroke (000-02 and 001-20 printed "h = 109.532 mm … 行程" beside H = 100)
    ("shaper.design_by_K", "h"): _n("h", "distance of the ram's guide from C", "滑枕导路至 C 的距离"),
    ("guide_bar.design_by_K", "CD"): _n("CD", "guide bar, C to D", "导杆"),
    ("guide_bar.design_by_K", "DE"): _n("DE", "coupler to the ram", "连杆"),
    # a crank-slider has no rocker: its link 3 is the slider (400-05 printed "P13 … 曲柄与摇杆的瞬心")
    ("crank_slider.instant_centres", "P13"): _n("P13", "instant centre of crank and slider", "曲柄与滑块的瞬心"),
}
"""Printed names that differ by recipe (an arm's ω2 is not a coupler's; a cam follower's a is not a centre
distance): looked up before :data:`NAMES`."""

SIDES: dict[tuple[str, str], tuple[tuple[str, str], tuple[str, str]]] = {
    ("cam.base_radius", "e"): (("axis right of O", "导路在 O 右侧"), ("axis left of O", "导路在 O 左侧")),
}
"""Signed answers whose Results line says the side in words, by recipe: (the words of a positive value, of a
negative one), English and Chinese. 200-11 printed "e = −5.657 mm" under a dimension "e=5.66" with the side only in
the Chinese convention "正值：导路在 O 右侧"; the line now reads "e = −5.657 mm, axis left of O", the dimension
"e=−5.66" (signed as the recipe defines e)."""


def side_words(answer: str, recipe: str, value: Any) -> tuple[str, str] | None:
    """The side a signed ``answer`` of ``recipe`` lies on in words (English, Chinese); None for an answer without
    a side (:data:`SIDES`) and for a value that prints as zero.

    >>> side_words("e", "cam.base_radius", -5.657), side_words("e", "cam.base_radius", 0.0)
    (('axis left of O', '导路在 O 左侧'), None)
    """
    sides = SIDES.get((recipe, answer))
    if sides is None or isinstance(value, (bool, str, tuple, list)) or fixed(float(value)) == "0.000":
        return None
    return sides[float(value) < 0]

UNITS = {"deg": "°", "": "", "bool": "", "point": "", "choice": "", "table": "", "interval": " mm"}
"""How a unit follows a number (any other unit: a space and the unit as the recipe names it, e.g. ``rad/s²``)."""


def unit_text(unit: str) -> str:
    """The unit as printed after a number.

    >>> unit_text("deg"), unit_text("mm[]"), unit_text("rad/s²"), unit_text("")
    ('°', ' mm', ' rad/s²', '')
    """
    u = unit.removesuffix("[]")
    return UNITS[u] if u in UNITS else f" {u}"


KNIFE_OFF_SHEET: dict[str, frozenset[str]] = {
    "cam.translating": frozenset({"rho_min_actual", "undercut"}),
    "cam.oscillating": frozenset({"rho_min_actual", "undercut"}),
    "cam.eccentric": frozenset({"r0_actual"}),
}
"""The answers a knife-edge cam's figure does not print, by recipe: a knife edge has no roller, so its actual
profile IS the pitch curve — ρa,min is ρmin (printed once, as the profile's), r0′ is r0, and it cannot undercut
(``undercut`` is always false). The JSON keeps these answers (a public contract) with those values; a figure
prints one that a problem's textbook printed (:func:`on_sheet`)."""

KNIFE_NAMES: dict[str, AnswerName] = {
    "rho_min_pitch": _n("ρmin", "profile (the pitch curve), least radius of curvature", "凸轮廓线最小曲率半径"),
}
"""A knife edge's printed names: its profile is the pitch curve (001-23a printed ρmin as the "pitch curve's" and
ρa,min as the "actual profile's", the same number twice)."""


FLAT_OFF_SHEET: dict[str, frozenset[str]] = {
    "cam.translating": frozenset({"undercut"}),
    "cam.oscillating": frozenset({"undercut"}),
}
"""The answers a flat-faced cam's figure does not print, by recipe: a flat face's profile condition is convexity
(ρ > 0 everywhere), and its ``undercut`` is only ``not convex`` — the sheet printed "undercut: no" beside
"profile convex: yes", one idea twice. It prints "profile convex" (``convex``) alone; the JSON keeps ``undercut``
(a public contract, = not ``convex``)."""


def knife(given: Mapping[str, Any] | None) -> bool:
    """Whether ``given`` describe a cam with a knife-edge follower."""
    return given is not None and given.get("follower") == "knife"


def flat(given: Mapping[str, Any] | None) -> bool:
    """Whether ``given`` describe a cam with a flat-faced follower."""
    return given is not None and given.get("follower") == "flat"


def on_sheet(answer: str, recipe: str, given: Mapping[str, Any] | None, printed: bool = False) -> bool:
    """Whether a figure (its Results block, the player, the terminal's summary) prints ``answer``: not a knife
    edge's ρa,min, r0′ or undercut (:data:`KNIFE_OFF_SHEET`), nor a flat face's undercut (:data:`FLAT_OFF_SHEET`:
    its convexity says it), unless the textbook ``printed`` it.

    >>> on_sheet("undercut", "cam.translating", {"follower": "knife"}), on_sheet("undercut", "cam.translating",
    ...                                                                          {"follower": "roller"})
    (False, True)
    >>> on_sheet("rho_min_actual", "cam.oscillating", {"follower": "knife"}, printed=True)
    True
    >>> on_sheet("undercut", "cam.translating", {"follower": "flat"}), on_sheet("convex", "cam.translating",
    ...                                                                         {"follower": "flat"})
    (False, True)
    """
    off = KNIFE_OFF_SHEET if knife(given) else FLAT_OFF_SHEET if flat(given) else {}
    return printed or answer not in off.get(recipe, ())


def name_of(answer: str, recipe: str = "", given: Mapping[str, Any] | None = None) -> AnswerName:
    """The printed name of ``answer`` (of ``recipe`` when it names it its own way: :data:`RECIPE_NAMES`; a
    fallback for a name not in :data:`NAMES`). With the problem's ``given``, a four-bar analysis names the link
    at each pivot of its frame (:func:`pivot_links`): "AD is a crank", not "the link at the first pivot".

    >>> name_of("theta").symbol, name_of("new_answer").symbol, name_of("omega2", "cam.oscillating").zh
    ('θ', 'new answer', '摆杆角速度')
    >>> name_of("output_crank", "four_bar.analysis", {"frame": "AB"}).en
    'BC is a crank'
    """
    if recipe == "four_bar.analysis" and answer in ("input_crank", "output_crank") and given is not None:
        link = pivot_links(str(given.get("frame") or "AD"))[answer == "output_crank"]
        return _b(f"{link} is a crank", f"{link} 为曲柄")
    if answer in KNIFE_NAMES and knife(given):
        return KNIFE_NAMES[answer]
    return RECIPE_NAMES.get((recipe, answer)) or NAMES.get(answer) or AnswerName(answer.replace("_", " "), "", "")


def pivot_links(frame: str) -> tuple[str, str]:
    """The links of the chain A–B–C–D–A at the first and the second pivot of ``frame``, the other than the frame.

    >>> pivot_links("AD"), pivot_links("AB"), pivot_links("CD")
    (('AB', 'CD'), ('AD', 'BC'), ('BC', 'AD'))
    """
    chain = "ABCD"
    out = []
    for pivot, other in ((frame[0], frame[1]), (frame[1], frame[0])):
        i = chain.index(pivot)
        (end,) = {chain[i - 1], chain[(i + 1) % 4]} - {other}
        out.append("".join(sorted(pivot + end)))
    return out[0], out[1]


def fixed(x: float) -> str:
    """A number with 3 decimals; one that rounds to zero prints ``0.000``, never ``-0.000``.

    >>> fixed(-0.0000001), fixed(-2.5), fixed(float("inf"))
    ('0.000', '-2.500', '∞')
    """
    if x == float("inf"):
        return "∞"
    t = f"{x:.3f}"
    return t[1:] if t == "-0.000" else t


def _number(v: float, unit: str) -> str:
    return f"{fixed(v)}{unit_text(unit)}"


def percent(rel: float) -> str:
    """A relative deviation in per cent, signed, 2 decimals; one that rounds to zero prints ``0.00 %``.

    >>> percent(-1e-6), percent(0.0123)
    ('0.00 %', '+1.23 %')
    """
    t = f"{100 * rel:+.2f}"
    return ("0.00" if t in ("+0.00", "-0.00") else t) + " %"


def shown_printed(v: Any, unit: str, lang: str = "en") -> str:
    """A textbook's printed value as the remark shows it: a number as printed (``%g``), a yes/no answer (the
    problem file writes 0 or 1) as the word.

    >>> shown_printed(12.5, "deg"), shown_printed(0, "bool"), shown_printed(1, "bool", "zh")
    ('12.5', 'no', '是')
    """
    if unit == "bool" or isinstance(v, bool):
        return shown_value(bool(v), "bool", lang)
    return f"{v:g}"


POINTS = frozenset({"A", "D", "C1", "F1", "E1", "P13", "P24"})
"""Answers that are a point [x, y]: printed as coordinates ``(x, y)``."""


def _intervals(v: Sequence[Sequence[float]], unit: str, lang: str) -> str:
    """A union of intervals as mathematics writes it (an unbounded end open: ``[610.000, ∞)``); none: ``none``.

    >>> _intervals([(0.0, 130.0), (190.0, float("inf"))], "interval[]", "en")
    '[0.000, 130.000] ∪ [190.000, ∞) mm'
    >>> _intervals([], "interval[]", "en"), _intervals([], "interval[]", "zh")
    ('none', '无')
    """
    if not v:
        return "无" if lang == "zh" else "none"
    return " ∪ ".join(f"[{fixed(lo)}, {fixed(hi)}" + (")" if hi == float("inf") else "]") for lo, hi in v) \
        + unit_text(unit)


def shown_value(v: Any, unit: str, lang: str = "en", answer: str = "") -> str:
    """A value as printed: 3 decimals and its unit, a point as ``(x, y)``, a list as its numbers, a union of
    intervals as mathematics writes it, a yes/no answer as a word.

    >>> shown_value((1.0, 2.5), "mm[]"), shown_value(True, "bool", "zh"), shown_value(1.0, "")
    ('1.000, 2.500 mm', '是', '1.000')
    >>> shown_value((64.375, 60.0), "mm[]", answer="A")
    '(64.375, 60.000) mm'
    """
    if isinstance(v, bool):
        return ("是" if v else "否") if lang == "zh" else ("yes" if v else "no")
    if isinstance(v, str):                                  # a word (a choice): the chain's type …
        return WORDS.get(v, (v, v))[1 if lang == "zh" else 0]
    if unit == "interval[]":
        return _intervals(v, unit, lang)
    if isinstance(v, (tuple, list)):
        body = ", ".join(fixed(float(x)) for x in v)
        return (f"({body})" if answer in POINTS and len(v) == 2 else body) + unit_text(unit)
    return _number(float(v), unit)


WORDS = {"crank-rocker": ("crank-rocker", "曲柄摇杆机构"), "double-crank": ("double-crank", "双曲柄机构"),
         "double-rocker": ("double-rocker", "双摇杆机构"), "change-point": ("change-point", "变点机构"),
         "immovable": ("immovable", "不能运动")}
"""Answers that are words, printed in each language."""


def _remarks(twin: bool | None, printed: Sequence[str], lang: str) -> str:
    parts = []
    if twin is not None:
        parts.append(("与解析解一致" if twin else "与解析解不符") if lang == "zh" else
                     ("= analytic" if twin else "≠ analytic"))
    if printed:
        parts.append(("教材 " if lang == "zh" else "textbook ") + ("；" if lang == "zh" else "; ").join(printed))
    if not parts:
        return ""
    return f"（{'；'.join(parts)}）" if lang == "zh" else f" ({'; '.join(parts)})"


def _head(nm: AnswerName, value: Any, unit: str, lang: str, answer: str, at: Sequence[float]) -> str:
    """``symbol = value`` of a number; a list at the cam angles ``at`` as the function of δ it is
    (``s(0°, 30°) = 0.000, 2.000 mm``), a list of one symbol's positions indexed (``φ1 = …°, φ2 = …°``)."""
    if isinstance(value, (tuple, list)) and unit.endswith("[]") and unit != "interval[]" and answer not in POINTS:
        u = unit_text(unit)
        each = u if u == "°" else ""
        values = [fixed(float(x)) + each for x in value]
        if at and len(at) == len(value):
            return f"{nm.symbol}({', '.join(f'{a:g}°' for a in at)}) = {', '.join(values)}{'' if each else u}"
        if len(nm.symbol) == 1:
            return ", ".join(f"{nm.symbol}{i} = {x}{'' if each else u}" for i, x in enumerate(values, 1))
    return f"{nm.symbol} = {shown_value(value, unit, lang, answer)}"


def result_line(answer: str, value: Any, unit: str, *, twin: bool | None = None, printed: Sequence[str] = (),
                lang: str = "en", recipe: str = "", at: Sequence[float] = (),
                given: Mapping[str, Any] | None = None) -> str:
    """One result line of a drawing: the answer by its symbol (a number) or as a statement (yes/no), its value,
    what agreed with what (``twin``: the construction against the analytic twin) and the textbook's printed
    values with their deviation (``printed``, already worded).

    ``lang`` is ``en``, ``zh`` or ``both`` (the English line, then the Chinese words); ``at``: the cam angles
    (deg) a list answer is given at; ``given``: the problem's givens, when a name depends on them
    (:func:`name_of`).

    >>> result_line("s", (0.0, 2.0), "mm[]", at=(0.0, 15.0))
    's(0°, 15°) = 0.000, 2.000 mm'
    >>> result_line("phi", (-137.015, 163.5), "deg[]")
    'φ1 = -137.015°, φ2 = 163.500°'
    >>> result_line("double_crank", [], "interval[]", lang="both")
    'double-crank: none  双曲柄机构的杆长范围：无'
    >>> result_line("e", -5.657, "mm", twin=True, lang="both", recipe="cam.base_radius")
    'e = -5.657 mm, axis left of O (= analytic)  偏距（导路在 O 左侧）'
    """
    nm = name_of(answer, recipe, given)
    side = side_words(answer, recipe, value)
    if side is not None:                            # the words of a signed answer say its side, not the rule
        nm = _n(nm.symbol, nm.en, f"{nm.zh.split('（')[0]}（{side[1]}）")
    is_bool = isinstance(value, bool) or unit == "bool" or (not nm.symbol and unit == "")
    if is_bool:
        value = bool(value)
    empty = unit == "interval[]" and not value
    if lang == "both":
        en = result_line(answer, value, unit, twin=twin, printed=printed, lang="en", recipe=recipe, at=at,
                         given=given)
        if not nm.zh:
            return en
        return f"{en}  {nm.zh}：{shown_value(value, unit, 'zh', answer)}" if is_bool or empty else f"{en}  {nm.zh}"
    shown = shown_value(value, unit, lang, answer)
    if lang == "zh":
        head = f"{nm.zh or nm.en}：{shown}" if is_bool or empty else \
            f"{nm.zh + ' ' if nm.zh else ''}{_head(nm, value, unit, lang, answer, at)}"
    else:
        head = f"{nm.en or nm.symbol}: {shown}" if is_bool else (
            f"{nm.symbol}: {shown}" if empty else _head(nm, value, unit, lang, answer, at))
        head += f", {side[0]}" if side is not None else ""
    return head + _remarks(twin, printed, lang)


def entries(symbol: str, index: Sequence[int], at: Sequence[float] = ()) -> str:
    """Entries ``index`` (from 0) of a list answer named as its Results line names them: at the cam angles ``at``
    as the function of δ it is (``ψ(6°, 8°)``), a one-letter symbol's positions by their number from 1 (``φ2``),
    else by the list's index (``xp[0…4]``).

    >>> entries("ψ", [2, 3, 4], (2, 4, 6, 8, 10)), entries("φ", [1]), entries("xp", [0, 1, 2])
    ('ψ(6°, 8°, 10°)', 'φ2', 'xp[0…2]')
    """
    if at and all(0 <= i < len(at) for i in index):
        return f"{symbol}({', '.join(f'{at[i]:g}°' for i in index)})"
    if len(symbol) == 1:
        return ", ".join(f"{symbol}{i + 1}" for i in index)
    return f"{symbol}[{index[0]}]" if len(index) == 1 else f"{symbol}[{min(index)}…{max(index)}]"


_DOUBTFUL = re.compile(r"published (?P<q>\w+)(?P<i>\[\d+\])? = \S+ is doubtful: it deviates from the exact "
                                     r"\S+ by .+?, beyond drafting accuracy \(±(?P<acc>.+?)\)")


def brief_warnings(warnings: Sequence[str], lang: str, sheet: int | str,
                   at: Mapping[str, Sequence[float]] | None = None) -> list[str]:
    """The warnings as sheet 1 prints them when the full block finds no room there: every doubtful printed answer
    in one line (its symbol; a list's entries as its Results line names them, :func:`entries`: the Results lines
    carry each deviation), the others as :func:`geomcon.render.warning_words.warning_lines` words them; the full
    sentences stand on sheet ``sheet`` (``"{sheet}"``: filled in when the sheets are counted). ``at``: the cam
    angles of the list answers given at angles, by answer.

    >>> brief_warnings(["published vD = 330 is doubtful: it deviates from the exact 385.405 by -14.38 %, beyond "
    ...                 "drafting accuracy (±3 %)", "published pitch_x[0] = 1 is doubtful: it deviates from the exact 2 "
    ...                 "by -50 %, beyond drafting accuracy (±3 %)", "published pitch_x[1] = 1 is doubtful: it "
    ...                 "deviates from the exact 2 by -50 %, beyond drafting accuracy (±3 %)"], "en", 2)
    ['printed vD, xp[0…1] doubtful: beyond drafting accuracy (±3 %); see sheet 2']
    >>> brief_warnings([f"published psi[{i}] = 1 is doubtful: it deviates from the exact 2 by -50 %, beyond drafting "
    ...                 "accuracy (±3 %)" for i in (2, 3)], "en", 3, at={"psi": (2, 4, 6, 8)})
    ['printed ψ(6°, 8°) doubtful: beyond drafting accuracy (±3 %); see sheet 3']
    >>> brief_warnings(["published vD = 330 is doubtful: it deviates from the exact 385.405 by -14.38 %, beyond "
    ...                 "drafting accuracy (±3 %)"], "zh", 3)
    ['教材答案 vD 存疑：超出作图精度（±3 %），详见第 3 张']
    """
    from .warning_words import warning_lines
    doubtful: dict[str, list[int]] = {}
    acc, rest = "", []
    for w in warnings:
        m = _DOUBTFUL.fullmatch(w)
        if m is None:
            rest.append(w)
            continue
        acc = m["acc"]
        doubtful.setdefault(m["q"], []).extend([int(m["i"][1:-1])] if m["i"] else [])
    out = []
    if doubtful:
        names = []
        for q, idx in doubtful.items():
            sym = name_of(q).symbol
            names.append(entries(sym, sorted(idx), (at or {}).get(q, ())) if idx else sym)
        en = f"printed {', '.join(names)} doubtful: beyond drafting accuracy (±{acc}); see sheet {sheet}"
        zh = f"教材答案 {'、'.join(names)} 存疑：超出作图精度（±{acc}），详见第 {sheet} 张"
        out += [en] if lang == "en" else [zh] if lang == "zh" else [en, zh]
    return out + warning_lines(rest, lang, at)


def brief_printed(printed: Sequence[tuple[str, str, bool]], lang: str) -> list[str]:
    """The printed answers of one result as its brief line remarks on them: one printed value as the full line
    does; several (a list's entries) by how many are doubtful, their values and deviations on the results sheet.

    >>> brief_printed([("-33.78", "+26.03 %", True), ("-43.21", "+20.72 %", True)], "en")
    ['2 of 2 doubtful']
    >>> brief_printed([("220", "-29.97 %", True)], "zh"), brief_printed([("1", "0.1 %", False)] * 3, "en")
    (['220，-29.97 %，存疑'], ['3 within drafting accuracy'])
    """
    zh = lang == "zh"
    if len(printed) == 1:
        p, how, doubt = printed[0]
        sep = "，" if zh else ", "
        return [p + (f"{sep}{how}" if how else "") + ((sep + ("存疑" if zh else "doubtful")) if doubt else "")]
    n = sum(d for _, _, d in printed)
    if not n:
        return [f"{len(printed)} 个均在作图精度内" if zh else f"{len(printed)} within drafting accuracy"]
    return [f"{len(printed)} 个中 {n} 个存疑" if zh else f"{n} of {len(printed)} doubtful"]


__all__ = ["AnswerName", "brief_printed", "brief_warnings", "entries", "flat", "FLAT_OFF_SHEET", "KNIFE_NAMES", "KNIFE_OFF_SHEET", "knife", "NAMES", "on_sheet", "POINTS", "fixed", "RECIPE_NAMES", "name_of", "percent", "pivot_links", "result_line", "shown_printed", "side_words", "SIDES",
           "shown_value", "unit_text"]
