"""Statement templates (English and Chinese) and the one way they are filled.

A template is plain text with ``{given}`` placeholders; :func:`fill` replaces each by the variant's value as
a teacher writes it (``1.25``, ``90``, a motion program in words). Templates, and a spec's own statements,
are never evaluated: no ``str.format`` (which reads attributes and indexes), only a scan for ``{name}``,
``{{`` and ``}}``.

Each recipe form has a default template; the sentence asking for the answers (:func:`find_sentence`) and,
when a variant has several valid solutions, the sentence naming the textbook's choice (:data:`CHOICE`) are
added to it. A recipe without a template of its own gets :func:`generic_template` (its title and its givens).

Examples
--------
>>> fill("K = {K}, CD = {CD} mm {{sic}}", {"K": "1.25", "CD": "90"})
'K = 1.25, CD = 90 mm {sic}'
>>> en, zh = default_template("crank_rocker.design_by_K", {"K": 1.25, "CD": 90, "psi": 40, "BC": 95})
>>> fill(en, shown_givens("crank_rocker.design_by_K", {"K": 1.25, "CD": 90, "psi": 40, "BC": 95}, "en"))
'Design a crank-rocker ABCD by its time-ratio coefficient K = 1.25: the rocker CD = 90 mm swings through ψ = 40° between its extreme positions DC1 and DC2, and the coupler is BC = 95 mm.'
"""
from __future__ import annotations

import re
from typing import Any, Mapping

_TOKEN = re.compile(r"\{\{|\}\}|\{([A-Za-z_][A-Za-z0-9_]*)\}")


def fill(template: str, values: Mapping[str, str]) -> str:
    """``template`` with each ``{name}`` replaced by ``values[name]`` and ``{{``, ``}}`` by braces; nothing
    else is interpreted. A placeholder missing from ``values`` raises KeyError (specs are checked first)."""
    def one(m: re.Match) -> str:
        t = m.group(0)
        if t == "{{":
            return "{"
        if t == "}}":
            return "}"
        return values[m.group(1)]
    return _TOKEN.sub(one, template)


# ------------------------------------------------------------------------------------------- values in words
LAWS = {"uniform": ("uniform velocity", "等速运动"), "parabolic": ("constant acceleration (parabolic)", "等加速等减速运动"),
        "cosine": ("cosine acceleration (simple harmonic)", "余弦加速度运动"),
        "cycloidal": ("sine acceleration (cycloidal)", "正弦加速度运动"),
        "poly345": ("3-4-5 polynomial", "3-4-5 多项式运动"),
        "double_harmonic": ("double-harmonic", "双谐波运动"),
        "modified_trapezoid": ("modified trapezoidal acceleration", "改进梯形加速度运动"),
        "modified_sine": ("modified sine acceleration", "改进正弦加速度运动"),
        "poly": ("polynomial", "多项式运动"), "table": ("tabulated", "列表给定的运动")}
FOLLOWERS = {"knife": ("knife-edge", "尖顶"), "roller": ("roller", "滚子"), "flat": ("flat-faced", "平底")}
ROTATION = {"ccw": ("counter-clockwise", "逆时针"), "cw": ("clockwise", "顺时针")}
SIDES = {"above": ("above", "上方"), "below": ("below", "下方")}


def number(x: Any) -> str:
    """A number as a teacher writes it: ``90``, ``1.25``, ``0.1``.

    >>> number(90.0), number(1.25), number(2), number(1e-7)
    ('90', '1.25', '2', '1e-07')
    """
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, int):
        return str(x)
    x = float(x)
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(x) if 1e-4 <= abs(x) < 1e15 else f"{x:g}"


def _law_numbers(row: Mapping[str, Any], lang: str) -> str:
    """The numbers of a parametrised law in words: a polynomial's coefficients, a table's points.

    >>> _law_numbers({"law": "poly", "coefficients": [0, 0, 3, -2]}, "en")
    ' (f(x) = Σ c_k x^k with c = (0, 0, 3, -2), x = δ/Φ)'
    >>> _law_numbers({"law": "table", "points": [[0, 0], [0.5, 0.4], [1, 1]]}, "zh")
    '，过点 (x, f) = (0, 0)、(0.5, 0.4)、(1, 1) 的三次样条（端点速度为零）'
    """
    if row.get("law") == "poly" and isinstance(row.get("coefficients"), (list, tuple)):
        c = ", ".join(number(v) for v in row["coefficients"])
        return (f" (f(x) = Σ c_k x^k with c = ({c}), x = δ/Φ)", f" f(x) = Σ c_k x^k,c = ({c}),x = δ/Φ")[lang == "zh"]
    if row.get("law") == "table" and isinstance(row.get("points"), (list, tuple)):
        pts = [f"({number(p[0])}, {number(p[1])})" for p in row["points"] if isinstance(p, (list, tuple)) and len(p) == 2]
        if lang == "zh":
            return "，过点 (x, f) = " + "、".join(pts) + " 的三次样条（端点速度为零）"
        return " (the clamped cubic spline through (x, f) = " + ", ".join(pts) + ")"
    return ""


def program_words(program: Any, lang: str) -> str:
    """A cam's motion program in words.

    >>> program_words([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 240}], "en")
    'rise through 120° with cosine acceleration (simple harmonic) motion, dwell 240°'
    >>> program_words([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
    ...                {"kind": "return", "angle": 90, "law": "cycloidal"}, {"kind": "dwell", "angle": 90}], "zh")
    '推程运动角 120°（余弦加速度运动），远休止角 60°，回程运动角 90°（正弦加速度运动），近休止角 90°'
    """
    parts = []
    last = None
    for row in program if isinstance(program, (list, tuple)) else ():
        kind, angle, law = row.get("kind"), number(row.get("angle", 0)), row.get("law", "")
        en_law, zh_law = LAWS.get(law, (str(law), str(law)))
        en_more, zh_law = _law_numbers(row, "en"), zh_law + _law_numbers(row, "zh")
        if lang == "zh":
            if kind == "dwell":
                word = "远休止角" if last == "rise" else "近休止角"
                parts.append(f"{word} {angle}°")
            else:
                parts.append(f"{'推程运动角' if kind == 'rise' else '回程运动角'} {angle}°（{zh_law}）")
        else:
            if kind == "dwell":
                parts.append(f"dwell {angle}°")
            else:
                parts.append(f"{kind} through {angle}° with {en_law} motion{en_more}")
        last = kind
    return ("，".join(parts)) if lang == "zh" else ", ".join(parts)


def shown_givens(recipe: str, given: Mapping[str, Any], lang: str) -> dict[str, str]:
    """Every given of a variant as text for a statement (numbers as written, a program, a follower, a sense of
    rotation in words)."""
    out: dict[str, str] = {}
    k = 1 if lang == "zh" else 0
    for name, v in given.items():
        if name == "program":
            out[name] = program_words(v, lang)
        elif name == "follower":
            out[name] = FOLLOWERS.get(v, (str(v), str(v)))[k]
        elif name == "rotation":
            out[name] = ROTATION.get(v, (str(v), str(v)))[k]
        elif name == "branch":
            out[name] = SIDES.get(v, (str(v), str(v)))[k]
        elif isinstance(v, (list, tuple)):
            out[name] = ", ".join(number(x) for x in v)
        elif isinstance(v, str):
            out[name] = v
        elif v is not None:
            out[name] = number(v)
    return out


# ------------------------------------------------------------------------------------------- templates
_DBK_INTRO = ("Design a crank-rocker ABCD by its time-ratio coefficient K = {K}: ",
              "按行程速比系数 K = {K} 设计曲柄摇杆机构 ABCD：")
_DBK_POSITIONS = ("the rocker CD = {CD} mm swings through ψ = {psi}° between its extreme positions DC1 and DC2",
                  "摇杆长 CD = {CD} mm，摆角 ψ = {psi}°（极限位置 DC1、DC2）")
_DBK_DIRECTIONS = ("the rocker CD = {CD} mm has its extreme positions DC1 and DC2 at {phi1}° and {phi2}° "
                   "counter-clockwise from the horizontal through D",
                   "摇杆长 CD = {CD} mm，其两极限位置 DC1、DC2 与过 D 的水平线逆时针成 {phi1}° 和 {phi2}°")
_DBK_CLOSING = {
    "BC": (", and the coupler is BC = {BC} mm.", "，连杆长 BC = {BC} mm。"),
    "AB": (", and the crank is AB = {AB} mm.", "，曲柄长 AB = {AB} mm。"),
    "AC1": (", and the pivot A lies AC1 = {AC1} mm from C1.", "，曲柄转动中心 A 与 C1 相距 AC1 = {AC1} mm。"),
    "frame_line": (", and the crank's pivot A lies on the horizontal through D.", "，曲柄转动中心 A 位于过 D 的水平线上。"),
    "AD": (", and the frame is AD = {AD} mm.", "，机架长 AD = {AD} mm。"),
}

TEMPLATES: dict[str, dict[str, tuple[str, str]]] = {
    "crank_rocker.design_by_K": {
        **{f"psi+{c}": (_DBK_INTRO[0] + _DBK_POSITIONS[0] + e, _DBK_INTRO[1] + _DBK_POSITIONS[1] + z)
           for c, (e, z) in _DBK_CLOSING.items()},
        **{f"phi1+{c}": (_DBK_INTRO[0] + _DBK_DIRECTIONS[0] + e, _DBK_INTRO[1] + _DBK_DIRECTIONS[1] + z)
           for c, (e, z) in _DBK_CLOSING.items()},
        "frame": ("Design a crank-rocker ABCD by its time-ratio coefficient K = {K}: the frame is AD = {AD} mm, "
                  "the rocker CD = {CD} mm, and in one extreme position the rocker makes ∠ADC1 = {phi}° with the frame.",
                  "按行程速比系数 K = {K} 设计曲柄摇杆机构 ABCD：机架长 AD = {AD} mm，摇杆长 CD = {CD} mm，"
                  "摇杆的一个极限位置与机架的夹角 ∠ADC1 = {phi}°。"),
        "links": ("Design a crank-rocker ABCD by its time-ratio coefficient K = {K}: the crank is AB = {AB} mm, the "
                  "coupler BC = {BC} mm and the rocker swings through ψ = {psi}°.",
                  "按行程速比系数 K = {K} 设计曲柄摇杆机构 ABCD：曲柄长 AB = {AB} mm，连杆长 BC = {BC} mm，"
                  "摇杆摆角 ψ = {psi}°。"),
        "crank_frame": ("Design a crank-rocker ABCD by its time-ratio coefficient K = {K}: the crank is AB = {AB} mm, "
                        "the frame AD = {AD} mm and the rocker swings through ψ = {psi}°. Find the coupler BC and the "
                        "rocker CD (every solution).",
                        "按行程速比系数 K = {K} 设计曲柄摇杆机构 ABCD：曲柄长 AB = {AB} mm，机架长 AD = {AD} mm，"
                        "摇杆摆角 ψ = {psi}°。求连杆 BC 和摇杆 CD（列出全部解）。"),
    },
    "crank_rocker.extremes": {
        "": ("A crank-rocker ABCD has the crank AB = {AB} mm, the coupler BC = {BC} mm, the rocker CD = {CD} mm "
             "and the frame AD = {AD} mm. Draw the rocker's two extreme positions.",
             "曲柄摇杆机构 ABCD 中，曲柄 AB = {AB} mm，连杆 BC = {BC} mm，摇杆 CD = {CD} mm，机架 AD = {AD} mm。"
             "作出摇杆的两个极限位置。"),
    },
    "four_bar.analysis": {
        "": ("A hinged four-bar chain has the links AB = {AB} mm, BC = {BC} mm, CD = {CD} mm and AD = {AD} mm, "
             "with {frame} fixed as the frame. Classify the mechanism, say which joints turn fully, and find θ, "
             "ψ, K and the smallest transmission angle where they exist.",
             "铰链四杆机构中 AB = {AB} mm，BC = {BC} mm，CD = {CD} mm，AD = {AD} mm，以 {frame} 为机架。"
             "判断机构类型，指出哪些转动副为周转副，并求其极位夹角 θ、摆角 ψ、行程速比系数 K 和最小传动角。"),
    },
    "four_bar.link_ranges": {
        "AB": ("In a hinged four-bar ABCD with {frame} as the frame, BC = {BC} mm, CD = {CD} mm, AD = {AD} mm; the link AB may have any "
               "length. For which lengths of AB is the chain a crank-rocker, a double-crank, a double-rocker, "
               "or not a mechanism?",
               "铰链四杆机构 ABCD 以 {frame} 为机架，BC = {BC} mm，CD = {CD} mm，AD = {AD} mm，杆 AB 的长度可任取。"
               "AB 取何值时为曲柄摇杆机构、双曲柄机构、双摇杆机构，何时不能成为机构？"),
        "BC": ("In a hinged four-bar ABCD with {frame} as the frame, AB = {AB} mm, CD = {CD} mm, AD = {AD} mm; the link BC may have any "
               "length. For which lengths of BC is the chain a crank-rocker, a double-crank, a double-rocker, "
               "or not a mechanism?",
               "铰链四杆机构 ABCD 以 {frame} 为机架，AB = {AB} mm，CD = {CD} mm，AD = {AD} mm，杆 BC 的长度可任取。"
               "BC 取何值时为曲柄摇杆机构、双曲柄机构、双摇杆机构，何时不能成为机构？"),
        "CD": ("In a hinged four-bar ABCD with {frame} as the frame, AB = {AB} mm, BC = {BC} mm, AD = {AD} mm; the link CD may have any "
               "length. For which lengths of CD is the chain a crank-rocker, a double-crank, a double-rocker, "
               "or not a mechanism?",
               "铰链四杆机构 ABCD 以 {frame} 为机架，AB = {AB} mm，BC = {BC} mm，AD = {AD} mm，杆 CD 的长度可任取。"
               "CD 取何值时为曲柄摇杆机构、双曲柄机构、双摇杆机构，何时不能成为机构？"),
        "AD": ("In a hinged four-bar ABCD with {frame} as the frame, AB = {AB} mm, BC = {BC} mm, CD = {CD} mm; the link AD may have any "
               "length. For which lengths of AD is the chain a crank-rocker, a double-crank, a double-rocker, "
               "or not a mechanism?",
               "铰链四杆机构 ABCD 以 {frame} 为机架，AB = {AB} mm，BC = {BC} mm，CD = {CD} mm，杆 AD 的长度可任取。"
               "AD 取何值时为曲柄摇杆机构、双曲柄机构、双摇杆机构，何时不能成为机构？"),
    },
    "guide_bar.extremes": {
        "": ("In an oscillating guide-bar mechanism the crank AB = {AB} mm turns about A and drives the guide bar "
             "about C, AC = {AC} mm. Find the crank angle θ between the extreme positions, the guide bar's swing ψ "
             "and the time-ratio coefficient K.",
             "摆动导杆机构中，曲柄 AB = {AB} mm 绕 A 转动，带动导杆绕 C 摆动，AC = {AC} mm。"
             "求极位夹角 θ、导杆摆角 ψ 和行程速比系数 K。"),
        "offset": ("In a guide-bar mechanism the crank AB = {AB} mm turns about A; the guide line of the bar pivoted "
                   "at C runs e = {e} mm from C, and AC = {AC} mm. Check that AB is a crank (AC > AB + e) and find "
                   "θ, the guide bar's swing ψ and K.",
                   "导杆机构中，曲柄 AB = {AB} mm 绕 A 转动，导杆绕 C 摆动，其导路与 C 的偏距 e = {e} mm，AC = {AC} mm。"
                   "验证 AB 为曲柄（AC > AB + e），并求极位夹角 θ、导杆摆角 ψ 和行程速比系数 K。"),
        "lever": ("In the crank and slotted-lever mechanism of a shaper the crank AB = {AB} mm turns about A, the "
                  "lever CD = {L} mm swings about C, AC = {AC} mm. Find θ, ψ, the time ratio K and the ram's stroke H.",
                  "牛头刨床的摆动导杆机构中，曲柄 AB = {AB} mm，导杆 CD = {L} mm 绕 C 摆动，AC = {AC} mm。"
                  "求极位夹角 θ、摆角 ψ、行程速比系数 K 和刨头行程 H。"),
        "offset+lever": ("In a guide-bar mechanism the crank AB = {AB} mm turns about A; the guide line of the lever "
                         "CD = {L} mm pivoted at C runs e = {e} mm from C, and AC = {AC} mm. Find θ, ψ, K and the "
                         "stroke H of the lever's end D.",
                         "导杆机构中，曲柄 AB = {AB} mm，导杆 CD = {L} mm 绕 C 摆动，其导路与 C 的偏距 e = {e} mm，"
                         "AC = {AC} mm。求极位夹角 θ、摆角 ψ、行程速比系数 K 和 D 点行程 H。"),
    },
    "rotating_guide_bar.extremes": {
        "": ("In a rotating guide-bar (Whitworth) mechanism the crank AB = {AB} mm turns about A and the guide bar "
             "about C, AC = {AC} mm; the ram's guide passes through C perpendicular to AC. Find the crank angles of "
             "the working and return strokes, θ and the time-ratio coefficient K.",
             "转动导杆机构中，曲柄 AB = {AB} mm 绕 A 转动，导杆绕 C 转动，AC = {AC} mm，滑枕导路过 C 且垂直于 AC。"
             "求工作行程与空回行程的曲柄转角、极位夹角 θ 和行程速比系数 K。"),
        "arm": ("In a rotating guide-bar (Whitworth) mechanism the crank AB = {AB} mm turns about A and the guide bar "
                "about C, AC = {AC} mm; the bar's arm CD = {CD} mm drives the ram, whose guide passes through C "
                "perpendicular to AC. Find θ, the time-ratio coefficient K and the ram's stroke S.",
                "转动导杆机构中，曲柄 AB = {AB} mm 绕 A 转动，导杆绕 C 转动，AC = {AC} mm，导杆臂 CD = {CD} mm "
                "带动滑枕，其导路过 C 且垂直于 AC。求极位夹角 θ、行程速比系数 K 和滑枕行程 S。"),
    },
    "crank_rocker.best_by_K": {
        "": ("Design a crank-rocker ABCD with the time-ratio coefficient K = {K}: the rocker swings through "
             "ψ = {psi}° and the frame is AD = {AD} mm. Of all such designs, find the one whose smallest "
             "transmission angle is the largest: AB, BC, CD and γmin.",
             "设计曲柄摇杆机构 ABCD，行程速比系数 K = {K}，摇杆摆角 ψ = {psi}°，机架长 AD = {AD} mm。"
             "在所有满足条件的设计中求最小传动角最大者的 AB、BC、CD 及 γmin。"),
    },
    "slotter.design_by_K": {
        "B1B2": ("Design the rotating guide-bar drive of a slotting machine by its time-ratio coefficient K = {K}: "
                 "the slider's stroke is H = {H} mm, and the path of the crank pin B crosses the slider's path ee at "
                 "two points B1B2 = {B1B2} mm apart.",
                 "按行程速比系数 K = {K} 设计插床的转动导杆机构：滑块行程 H = {H} mm，曲柄销 B 的轨迹与滑块导路 ee "
                 "的两交点相距 B1B2 = {B1B2} mm。"),
        "AB": ("Design the rotating guide-bar (Whitworth) drive of a slotting machine by its time-ratio coefficient "
               "K = {K}: the crank is AB = {AB} mm and the ram's stroke H = {H} mm, the ram's guide passing through "
               "the guide bar's pivot C perpendicular to AC. Find the centre distance AC and the arm CD.",
               "按行程速比系数 K = {K} 设计插床的转动导杆机构：曲柄 AB = {AB} mm，滑枕行程 H = {H} mm，"
               "滑枕导路过导杆转动中心 C 且垂直于 AC。求中心距 AC 和导杆臂长 CD。"),
        "AC": ("Design the rotating guide-bar (Whitworth) drive of a slotting machine by its time-ratio coefficient "
               "K = {K}: the centre distance is AC = {AC} mm and the ram's stroke H = {H} mm, the ram's guide passing "
               "through the guide bar's pivot C perpendicular to AC. Find the crank AB and the arm CD.",
               "按行程速比系数 K = {K} 设计插床的转动导杆机构：中心距 AC = {AC} mm，滑枕行程 H = {H} mm，"
               "滑枕导路过导杆转动中心 C 且垂直于 AC。求曲柄 AB 和导杆臂长 CD。"),
    },
    "crank_slider.design_by_K": {
        "e": ("Design an offset crank-slider by its time-ratio coefficient K = {K}: the slider's stroke is "
              "H = {H} mm and the offset e = {e} mm.",
              "按行程速比系数 K = {K} 设计偏置曲柄滑块机构：滑块行程 H = {H} mm，偏距 e = {e} mm。"),
        "AB": ("Design an offset crank-slider by its time-ratio coefficient K = {K}: the slider's stroke is "
               "H = {H} mm and the crank AB = {AB} mm.",
               "按行程速比系数 K = {K} 设计偏置曲柄滑块机构：滑块行程 H = {H} mm，曲柄长 AB = {AB} mm。"),
        "BC": ("Design an offset crank-slider by its time-ratio coefficient K = {K}: the slider's stroke is "
               "H = {H} mm and the connecting rod BC = {BC} mm.",
               "按行程速比系数 K = {K} 设计偏置曲柄滑块机构：滑块行程 H = {H} mm，连杆长 BC = {BC} mm。"),
    },
    "cam.translating": {
        "centric": ("A disc cam turning {rotation} drives a translating {follower} follower whose axis passes "
                    "through the cam's centre. Base circle r0 = {r0} mm, stroke h = {h} mm; motion program: "
                    "{program}.",
                    "一盘形凸轮{rotation}转动，推动对心直动{follower}从动件。基圆半径 r0 = {r0} mm，行程 h = {h} mm；"
                    "运动规律：{program}。"),
        "offset": ("A disc cam turning {rotation} drives a translating {follower} follower whose axis is offset "
                   "e = {e} mm to the right of the cam's centre. Base circle r0 = {r0} mm, stroke h = {h} mm; "
                   "motion program: {program}.",
                   "一盘形凸轮{rotation}转动，推动偏置直动{follower}从动件，从动件导路位于凸轮回转中心右侧，"
                   "偏距 e = {e} mm。基圆半径 r0 = {r0} mm，行程 h = {h} mm；运动规律：{program}。"),
    },
    "four_bar.kinematics": {
        "": ("In the four-bar ABCD the crank is AB = {AB} mm, the coupler BC = {BC} mm, the rocker CD = {CD} mm and "
             "the frame AD = {AD} mm. The crank stands at φ = {phi}° from AD and turns counter-clockwise positive at "
             "ω = {omega} rad/s with ε = {epsilon} rad/s². Draw the velocity and acceleration polygons.",
             "铰链四杆机构 ABCD 中，曲柄 AB = {AB} mm，连杆 BC = {BC} mm，摇杆 CD = {CD} mm，机架 AD = {AD} mm。"
             "曲柄与 AD 的夹角 φ = {phi}°，角速度 ω = {omega} rad/s，角加速度 ε = {epsilon} rad/s²（均以逆时针为正）。"
             "试用矢量方程图解法作速度多边形和加速度多边形。"),
        "E": ("In the four-bar ABCD the crank is AB = {AB} mm, the coupler BC = {BC} mm, the rocker CD = {CD} mm and "
              "the frame AD = {AD} mm; E is a point of the coupler with BE = {BE} mm and ∠CBE = {angle_CBE}°. The "
              "crank stands at φ = {phi}° from AD and turns counter-clockwise positive at ω = {omega} rad/s with "
              "ε = {epsilon} rad/s². Draw the velocity and acceleration polygons and find E's images by the image "
              "principle.",
              "铰链四杆机构 ABCD 中，曲柄 AB = {AB} mm，连杆 BC = {BC} mm，摇杆 CD = {CD} mm，机架 AD = {AD} mm；"
              "E 为连杆上一点，BE = {BE} mm，∠CBE = {angle_CBE}°。曲柄与 AD 的夹角 φ = {phi}°，角速度 ω = {omega} rad/s，"
              "角加速度 ε = {epsilon} rad/s²（均以逆时针为正）。试作速度多边形和加速度多边形，并用影像原理求 E 点的速度和加速度。"),
    },
    "crank_slider.kinematics": {
        "": ("In the offset crank-slider the crank is AB = {AB} mm, the rod BC = {BC} mm and the guide lies e = {e} mm "
             "below A. The crank stands at φ = {phi}° and turns counter-clockwise positive at ω = {omega} rad/s with "
             "ε = {epsilon} rad/s². Draw the velocity and acceleration polygons.",
             "偏置曲柄滑块机构中，曲柄 AB = {AB} mm，连杆 BC = {BC} mm，导路位于 A 下方 e = {e} mm。曲柄转角 φ = {phi}°，"
             "角速度 ω = {omega} rad/s，角加速度 ε = {epsilon} rad/s²（均以逆时针为正）。试作速度多边形和加速度多边形。"),
    },
    "guide_bar.kinematics": {
        "": ("In the oscillating guide-bar the crank is AB = {AB} mm and the guide's pivot C lies AC = {AC} mm below A. "
             "The crank stands at φ = {phi}° and turns counter-clockwise positive at ω = {omega} rad/s with "
             "ε = {epsilon} rad/s². Draw the velocity and acceleration polygons, the Coriolis component included.",
             "摆动导杆机构中，曲柄 AB = {AB} mm，导杆转动中心 C 位于 A 下方 AC = {AC} mm。曲柄转角 φ = {phi}°，"
             "角速度 ω = {omega} rad/s，角加速度 ε = {epsilon} rad/s²（均以逆时针为正）。试作速度多边形和加速度多边形"
             "（含哥氏加速度）。"),
    },
    "slotter.kinematics": {
        "": ("In the slotting machine the crank AB = {AB} mm turns about A; its block B slides on the guide bar, which "
             "turns about C, AC = {AC} mm to the left of A; the guide bar's arm CD = {CD} mm lies beyond C, and the "
             "coupler DE = {DE} mm drives the ram E on a vertical path CF = {CF} mm beyond C, E {branch} D. The crank "
             "stands at φ = {phi}° from +x and turns counter-clockwise positive at ω = {omega} rad/s with "
             "ε = {epsilon} rad/s². Draw the velocity and acceleration polygons, the Coriolis component included.",
             "插床机构中，曲柄 AB = {AB} mm 绕 A 转动，其上滑块 B 在导杆上滑动，导杆绕 C 摆动，C 在 A 左侧 AC = {AC} mm；"
             "导杆在 C 另一侧的臂长 CD = {CD} mm，连杆 DE = {DE} mm 带动滑枕 E 沿铅垂导路运动，导路在 C 外侧 CF = {CF} mm，"
             "E 在 D {branch}。曲柄转角 φ = {phi}°（自 +x 量起），角速度 ω = {omega} rad/s，角加速度 ε = {epsilon} rad/s²"
             "（均以逆时针为正）。试作速度多边形和加速度多边形（含哥氏加速度）。"),
    },
    "four_bar.instant_centres": {
        "": ("In the four-bar ABCD the crank is AB = {AB} mm, the coupler BC = {BC} mm, the rocker CD = {CD} mm and the "
             "frame AD = {AD} mm; the crank stands at φ = {phi}° from AD. Find all the instant centres (Kennedy's "
             "theorem for those that are not joints).",
             "铰链四杆机构 ABCD 中，曲柄 AB = {AB} mm，连杆 BC = {BC} mm，摇杆 CD = {CD} mm，机架 AD = {AD} mm，"
             "曲柄与 AD 的夹角 φ = {phi}°。求机构的全部瞬心（非铰链处的瞬心用三心定理求）。"),
    },
    "crank_slider.instant_centres": {
        "": ("In the offset crank-slider the crank is AB = {AB} mm, the rod BC = {BC} mm and the guide lies e = {e} mm "
             "below A; the crank stands at φ = {phi}°. Find all the instant centres (Kennedy's theorem; P34 lies at "
             "infinity perpendicular to the guide).",
             "偏置曲柄滑块机构中，曲柄 AB = {AB} mm，连杆 BC = {BC} mm，导路位于 A 下方 e = {e} mm，曲柄转角 φ = {phi}°。"
             "求机构的全部瞬心（P34 在垂直于导路的无穷远处，其余用三心定理求）。"),
    },
    "crank_slider.extremes": {
        "": ("An offset crank-slider has the crank AB = {AB} mm, the connecting rod BC = {BC} mm and the offset "
             "e = {e} mm of the slider's guide from A. Draw the slider's two extreme positions.",
             "偏置曲柄滑块机构中，曲柄 AB = {AB} mm，连杆 BC = {BC} mm，滑块导路相对 A 的偏距 e = {e} mm。"
             "作出滑块的两个极限位置。"),
    },
    "crank_slider.best_by_K": {
        "": ("Design an offset crank-slider with the time-ratio coefficient K = {K} and the slider's stroke "
             "H = {H} mm; of all such designs, take the one whose smallest transmission angle in the working "
             "stroke is the largest.",
             "设计偏置曲柄滑块机构，行程速比系数 K = {K}，滑块行程 H = {H} mm；在所有满足条件的设计中，"
             "取工作行程最小传动角最大者。"),
    },
    "guide_bar.design_by_K": {
        "AC": ("Design an oscillating guide-bar mechanism by its time-ratio coefficient K = {K}: the centre "
               "distance is AC = {AC} mm.",
               "按行程速比系数 K = {K} 设计摆动导杆机构，机架长（中心距）AC = {AC} mm。"),
        "AB": ("Design an oscillating guide-bar mechanism by its time-ratio coefficient K = {K}: the crank is "
               "AB = {AB} mm.",
               "按行程速比系数 K = {K} 设计摆动导杆机构，曲柄长 AB = {AB} mm。"),
    },
    "shaper.design_by_K": {
        "AC": ("Design the crank and slotted-lever (guide-bar) drive of a shaper by its time-ratio coefficient "
               "K = {K}: the ram's stroke is H = {H} mm and the centre distance AC = {AC} mm.",
               "按行程速比系数 K = {K} 设计牛头刨床的导杆机构：刨头行程 H = {H} mm，中心距 AC = {AC} mm。"),
        "AB": ("Design the crank and slotted-lever (guide-bar) drive of a shaper by its time-ratio coefficient "
               "K = {K}: the ram's stroke is H = {H} mm and the crank AB = {AB} mm.",
               "按行程速比系数 K = {K} 设计牛头刨床的导杆机构：刨头行程 H = {H} mm，曲柄长 AB = {AB} mm。"),
    },
    "four_bar.three_positions": {
        "": ("Design a hinged four-bar ABCD whose coupler BC takes three given positions: B1 ({B1}), C1 ({C1}); "
             "B2 ({B2}), C2 ({C2}); B3 ({B3}), C3 ({C3}) (coordinates in mm). Find the fixed pivots A and D "
             "(perpendicular bisectors) and the link lengths.",
             "设计铰链四杆机构 ABCD，使连杆 BC 依次占据三个给定位置：B1({B1})、C1({C1})；B2({B2})、C2({C2})；"
             "B3({B3})、C3({C3})（坐标，单位 mm）。用中垂线法求固定铰链 A、D 及各杆长度。"),
    },
    "four_bar.three_positions_fixed_pivots": {
        "": ("The fixed pivots of a hinged four-bar are A ({A}) and D ({D}); the input link's joint B takes the "
             "positions B1 ({B1}), B2 ({B2}), B3 ({B3}) (coordinates in mm)",
             "铰链四杆机构的固定铰链为 A({A})、D({D})，主动件上的铰链 B 依次位于 B1({B1})、B2({B2})、B3({B3})"
             "（坐标，单位 mm）"),
    },
    "four_bar.function_generation": {
        "": ("Design a hinged four-bar ABCD as a function generator: the frame is AD = {AD} mm and the crank "
             "AB = {AB} mm; the crank's directions φ = {phi}° (from A→D) are to correspond to the rocker's "
             "directions ψ = {psi}° (from AD extended beyond D). Find the joint C1 by the inversion method about "
             "D, the coupler BC and the rocker CD.",
             "按给定函数关系设计铰链四杆机构 ABCD：机架 AD = {AD} mm，曲柄 AB = {AB} mm，要求曲柄位置角 φ = {phi}°"
             "（自 A→D 量起）依次对应摇杆位置角 ψ = {psi}°（自 AD 延长线量起）。用反转法（绕 D 反转）求 C1 及连杆 BC、"
             "摇杆 CD 的长度。"),
    },
    "rocker_slider.three_positions": {
        "": ("A rocker turns about D ({D}) and drives a slider through a rod EF; the slider's guide passes "
             "through (0, {e}) mm. The rocker's marked line takes the directions ψ = {psi}° (from +x), and the "
             "slider's pin E is to be at s = {s} mm along the guide in the corresponding positions. Find the "
             "rod's joint F1 on the rocker by the inversion method, DF and EF.",
             "摇杆绕 D({D})转动，通过连杆 EF 带动滑块，滑块导路过点 (0, {e}) mm。摇杆标线依次位于 ψ = {psi}°"
             "（自 +x 量起），要求滑块铰链 E 相应位于导路上 s = {s} mm 处。用反转法求摇杆上的铰链 F1 及 DF、EF。"),
    },
    "rocker_slider.two_positions": {
        "": ("A rocker turns about D ({D}) and drives a slider through a rod EF; the slider's guide passes "
             "through (0, {e}) mm. The rocker's marked line takes the directions ψ = {psi}° (from +x) while the "
             "slider moves to s = {s} mm along the guide; the rod's joint on the rocker is F1 ({F1}) in position 1. "
             "Find the slider's joint E1 by the inversion method and the rod EF.",
             "摇杆绕 D({D})转动，通过连杆 EF 带动滑块，滑块导路过点 (0, {e}) mm。摇杆标线依次位于 ψ = {psi}°"
             "（自 +x 量起）时滑块相应位于导路上 s = {s} mm 处；连杆与摇杆的铰链在位置 1 为 F1({F1})。"
             "用反转法求滑块上的铰链 E1 及连杆 EF。"),
    },
    "cam.eccentric": {
        "": ("An eccentric circular disc of radius R = {R} mm turns {rotation} about O; its centre A lies "
             "OA = {OA} mm from O. It drives a {follower} follower.",
             "偏心圆盘凸轮半径 R = {R} mm，绕 O {rotation}转动，其几何中心 A 与 O 相距 OA = {OA} mm，"
             "推动{follower}从动件。"),
    },
    "cam.oscillating": {
        "omega": ("A disc cam turning {rotation} drives an oscillating {follower} follower: the arm's pivot A0 is "
             "a = {a} mm from the cam's centre O, the arm is L = {L} mm long, the base circle r0 = {r0} mm, and "
             "the arm swings through h = {h}°; motion program: {program}.",
             "一盘形凸轮{rotation}转动，推动摆动{follower}从动件：摆杆转轴 A0 与凸轮回转中心 O 相距 a = {a} mm，"
             "摆杆长 L = {L} mm，基圆半径 r0 = {r0} mm，最大摆角 h = {h}°；运动规律：{program}。"),
        "flat": ("A disc cam turning {rotation} drives an oscillating flat-faced follower: the arm's pivot A0 is "
                 "a = {a} mm from the cam's centre O, the base circle r0 = {r0} mm, and the arm swings through "
                 "h = {h}°; motion program: {program}.",
                 "一盘形凸轮{rotation}转动，推动摆动平底从动件：摆杆转轴 A0 与凸轮回转中心 O 相距 a = {a} mm，"
                 "基圆半径 r0 = {r0} mm，最大摆角 h = {h}°；运动规律：{program}。"),
    },
    "cam.base_radius": {
        "alpha": ("A disc cam turning {rotation} drives a translating roller (or knife-edge) follower through the "
                  "stroke h = {h} mm; motion program: {program}. The pressure angle must not exceed {alpha_allow}°.",
                  "一盘形凸轮{rotation}转动，推动直动滚子（或尖顶）从动件，行程 h = {h} mm；运动规律：{program}。"
                  "许用压力角 {alpha_allow}°。"),
        "oscillating": ("A disc cam turning {rotation} drives an oscillating roller (or knife-edge) follower whose arm "
                        "is L = {L} mm long and swings through h = {h}°; motion program: {program}. The pressure "
                        "angle must not exceed {alpha_allow}°.",
                        "一盘形凸轮{rotation}转动，推动摆动滚子（或尖顶）从动件，摆杆长 L = {L} mm，最大摆角 h = {h}°；"
                        "运动规律：{program}。许用压力角 {alpha_allow}°。"),
        "alpha+rho": ("A disc cam turning {rotation} drives a translating roller (or knife-edge) follower through the "
                      "stroke h = {h} mm; "
             "motion program: {program}. The pressure angle must not exceed {alpha_allow}° and the pitch curve's "
             "radius of curvature must be at least {rho_allow} mm. Find the smallest base circle.",
             "一盘形凸轮{rotation}转动，推动直动滚子（或尖顶）从动件，行程 h = {h} mm；运动规律：{program}。"
             "许用压力角 {alpha_allow}°，理论廓线曲率半径不得小于 {rho_allow} mm。求最小基圆半径。"),
        "arm+rho": ("A disc cam turning {rotation} swings a roller (or knife-edge) arm L = {L} mm long through h = {h}°; "
                    "motion program: {program}. The pressure angle must not exceed {alpha_allow}° and the pitch "
                    "curve's radius of curvature must be at least {rho_allow} mm. Find the smallest base circle, the "
                    "centre distance a and the initial arm angle ψ0.",
                    "一盘形凸轮{rotation}转动，推动摆动滚子（或尖顶）从动件，摆杆长 L = {L} mm，最大摆角 h = {h}°；"
                    "运动规律：{program}。许用压力角 {alpha_allow}°，理论廓线曲率半径不得小于 {rho_allow} mm。"
                    "求最小基圆半径、中心距 a 及初始摆角 ψ0。"),
        "flat": ("A disc cam turning {rotation} drives a translating flat-faced follower through the stroke h = {h} mm; "
                 "motion program: {program}. Contact stress asks the profile's radius of curvature to be at least "
                 "{rho_allow} mm everywhere. Find the smallest base circle.",
                 "一盘形凸轮{rotation}转动，推动直动平底从动件，行程 h = {h} mm；运动规律：{program}。"
                 "按接触应力要求，凸轮廓线各处曲率半径不得小于 {rho_allow} mm。求最小基圆半径。"),
    },
}
TEMPLATES["cam.oscillating"][""] = TEMPLATES["cam.oscillating"]["omega"]     # the text names no ω (OMEGA_WORDS does)
"""Default statements: recipe → form → (English, Chinese) text with ``{given}`` placeholders."""

CLAUSES: dict[str, tuple[tuple[str, tuple[str, str]], ...]] = {
    "crank_slider.best_by_K": (
        ("e_min", (" The offset e must be at least {e_min} mm.", "偏距 e 不得小于 {e_min} mm。")),
        ("e_max", (" The offset e must be at most {e_max} mm.", "偏距 e 不得大于 {e_max} mm。"))),
    "shaper.design_by_K": (
        ("alpha_allow", (" The pressure angle at the ram must not exceed {alpha_allow}°.", "刨头处的压力角不得超过 {alpha_allow}°。")),
        ("DE", (" The link DE driving the ram is {DE} mm long.", "带动刨头的连杆 DE = {DE} mm。"))),
    "slotter.design_by_K": (
        ("alpha_allow", (" The pressure angle at the ram must not exceed {alpha_allow}°.", "滑枕处的压力角不得超过 {alpha_allow}°。")),),
    "four_bar.three_positions_fixed_pivots": (
        ("K1", ("; a point K of the coupler passes through K1 ({K1}), K2 ({K2}), K3 ({K3})",
                "；连杆上一点 K 依次通过 K1({K1})、K2({K2})、K3({K3})")),
        ("coupler_angles", ("; the coupler line BK has the directions {coupler_angles}° in the three positions",
                            "；连杆标线 BK 在三个位置的方位角依次为 {coupler_angles}°")),
        ("", (". Find the coupler's joint C1 by the inversion method and the link lengths.",
              "。用反转法求连杆铰链 C1 及各杆长度。"))),
    "rocker_slider.three_positions": (
        ("guide_angle", (" The guide is inclined at {guide_angle}° to +x.", "导路与 +x 轴成 {guide_angle}°。")),),
    "rocker_slider.two_positions": (
        ("guide_angle", (" The guide is inclined at {guide_angle}° to +x.", "导路与 +x 轴成 {guide_angle}°。")),),
    "cam.eccentric": (
        ("e", (" The follower's axis is offset e = {e} mm to the right of O.", "从动件导路位于 O 右侧，偏距 e = {e} mm。")),
        ("a", (" The follower is an arm pivoted a = {a} mm from O, of length L = {L} mm.",
               "从动件为摆杆，其转轴与 O 相距 a = {a} mm，摆杆长 L = {L} mm。")),
        ("delta", (" In the position asked the cam has turned δ = {delta}° from the follower's lowest position.",
                   "所求位置为凸轮自从动件最低位置转过 δ = {delta}° 处。")),
        ("A_angle", (" In the position asked the ray O→A makes {A_angle}° with the perpendicular to the guide.",
                     "所求位置 O→A 与导路的垂线成 {A_angle}°。")),
        ("contact_angle", (" In the position asked the contact lies on the ray from A at {contact_angle}° to O→A.",
                           "所求位置的接触点位于自 A 出发、与 O→A 成 {contact_angle}° 的射线上。")),
        ("turn", (" The cam then turns a further {turn}°.", "凸轮再转过 {turn}°。"))),
    "cam.base_radius": (
        ("e", (" The offset is fixed at e = {e} mm.", "偏距取定为 e = {e} mm。")),
        ("a", (" The centre distance is fixed at a = {a} mm.", "中心距取定为 a = {a} mm。")),
        ("alpha_allow_return", (" On the return the pressure angle must not exceed {alpha_allow_return}°.",
                                "回程许用压力角 {alpha_allow_return}°。"))),
    "cam.oscillating": (
        ("face_offset", (" The flat face lies {face_offset} mm from the pivot A0, towards the cam.",
                         "平底与摆杆转轴 A0 相距 {face_offset} mm（偏向凸轮一侧）。")),),
}
"""Sentences added to a recipe form's statement for each optional given the variant has, in order (``""``:
always added, closing the sentence)."""

ROLLER = (" The roller's radius is rr = {rr} mm.", "滚子半径 rr = {rr} mm。")
"""Added to a cam statement when the follower has a roller."""
OMEGA_WORDS = (" The cam turns at a constant ω = {omega} rad/s.", "凸轮以等角速度 ω = {omega} rad/s 转动。")
"""Added to a cam statement when ω is given (the follower's speeds are then asked)."""
CAM_DRAW = (" Draw the cam profile by the inversion method.", "试用反转法绘制凸轮轮廓。")
"""Ends a cam statement (after the roller)."""

CHOICE: dict[str, tuple[str, str]] = {
    "crank_rocker.design_by_K": (
        "Where several designs satisfy the data, take the one with C1 the folded extreme position "
        "(AC1 = BC − AB); of those, the one with A on D's side of C1C2; then the shorter frame AD.",
        "若有多解，取 C1 为曲柄与连杆重叠共线的极限位置（AC1 = BC − AB）者；其中取 A 位于 C1C2 靠 D 一侧者；"
        "再取机架 AD 较短者。"),
}
"""The sentence naming the textbook's choice among several valid solutions, per recipe (the recipe's own
order of preference, :func:`geomcon.recipes.common.preference`)."""


def template_form(recipe: str, given: Mapping[str, Any]) -> str | None:
    """The key of :data:`TEMPLATES` [recipe] that fits these givens, or None.

    >>> template_form("crank_rocker.design_by_K", {"K": 1.5, "CD": 75, "AD": 100, "phi": 45})
    'frame'
    >>> template_form("cam.translating", {"follower": "roller", "r0": 40, "e": 0, "h": 20})
    'centric'
    """
    has = {k for k, v in given.items() if v is not None and v is not False}
    if recipe == "crank_rocker.design_by_K":
        if "CD" not in has:
            return "links" if "BC" in has else "crank_frame"
        if "phi" in has:
            return "frame"
        closing = [c for c in ("BC", "AB", "AC1", "frame_line", "AD") if c in has]
        head = "psi" if "psi" in has else "phi1"
        return f"{head}+{closing[0]}" if len(closing) == 1 else None
    if recipe == "crank_slider.design_by_K":
        return next((k for k in ("e", "AB", "BC") if k in has), None)
    if recipe == "guide_bar.extremes":
        return "+".join(w for w, k in (("offset", "e"), ("lever", "L")) if k in has and given[k] != 0)
    if recipe == "slotter.design_by_K":
        return next((k for k in ("B1B2", "AB", "AC") if k in has), None)
    if recipe in ("guide_bar.design_by_K", "shaper.design_by_K"):
        return next((k for k in ("AC", "AB") if k in has), None)
    if recipe == "rotating_guide_bar.extremes":
        return "arm" if "CD" in has else ""
    if recipe == "four_bar.link_ranges":                 # the form names the unknown link
        missing = [k for k in ("AB", "BC", "CD", "AD") if k not in has]
        return missing[0] if len(missing) == 1 else None
    if recipe == "cam.translating":
        return "offset" if given.get("e") not in (None, 0, 0.0) else "centric"
    if recipe == "four_bar.kinematics":
        return "E" if "BE" in has else ""
    if recipe == "cam.oscillating":
        return "flat" if given.get("follower") == "flat" else "omega" if "omega" in has else ""
    if recipe == "cam.base_radius":
        if given.get("motion") == "oscillating":
            if "rho_allow" in has:
                return "arm+rho" if "alpha_allow" in has and "L" in has else None
            return "oscillating" if "L" in has and "alpha_allow" in has else None
        if "rho_allow" not in has:
            return "alpha" if "alpha_allow" in has and given.get("follower") != "flat" else None
        return "flat" if given.get("follower") == "flat" else ("alpha+rho" if "alpha_allow" in has else None)
    if recipe in TEMPLATES:
        return ""
    return None


def default_template(recipe: str, given: Mapping[str, Any], title: str = "") -> tuple[str, str]:
    """The (English, Chinese) template of a variant: the recipe form's own, else :func:`generic_template`."""
    form = template_form(recipe, given)
    if form is None or form not in TEMPLATES.get(recipe, {}):
        return generic_template(title or recipe, given)
    en, zh = TEMPLATES[recipe][form]
    has = {k for k, v in given.items() if v is not None and v is not False}
    for name, (e, z) in CLAUSES.get(recipe, ()):
        if not name or name in has:
            en, zh = en + e, zh + z
    if recipe.startswith("cam."):
        if given.get("follower") == "roller" and given.get("rr") is not None:
            en, zh = en + ROLLER[0], zh + ROLLER[1]
        if given.get("omega") is not None:
            en, zh = en + OMEGA_WORDS[0], zh + OMEGA_WORDS[1]
        if recipe not in ("cam.base_radius", "cam.eccentric"):     # an eccentric disc's profile is its circle
            en, zh = en + CAM_DRAW[0], zh + CAM_DRAW[1]
    return en, zh


def generic_template(title: str, given: Mapping[str, Any]) -> tuple[str, str]:
    """A statement for any recipe: its title and its givens.

    >>> generic_template("Guide-bar: extreme positions", {"AB": 100, "AC": 200})[0]
    'Guide-bar: extreme positions. Given AB = {AB}, AC = {AC}.'
    """
    names = [k for k, v in given.items() if v is not None]
    listed = ", ".join(f"{k} = {{{k}}}" for k in names)
    safe = title.replace("{", "{{").replace("}", "}}")
    return f"{safe}. Given {listed}.", f"{safe}。已知 {listed}。"


# ------------------------------------------------------------------------------------------- the question
ANSWER_WORDS: dict[str, tuple[str, str]] = {
    "AB": ("the crank AB", "曲柄长 AB"), "BC": ("the coupler BC", "连杆长 BC"), "AD": ("the frame AD", "机架长 AD"),
    "CD": ("the rocker CD", "摇杆长 CD"), "AC1": ("the distance AC1", "AC1"), "AC2": ("the distance AC2", "AC2"),
    "e": ("the offset e", "偏距 e"), "H": ("the stroke H", "行程 H"),
    "theta": ("the crank angle between the extreme positions θ", "极位夹角 θ"),
    "psi": ("the rocker's swing ψ", "摇杆摆角 ψ"), "K": ("the time-ratio coefficient K", "行程速比系数 K"),
    "gamma_min": ("the smallest transmission angle γmin", "最小传动角 γmin"),
    "alpha_max": ("the largest pressure angle αmax", "最大压力角 αmax"),
    "angle_C1AD": ("the angle ∠C1AD", "∠C1AD"), "angle_C2AD": ("the angle ∠C2AD", "∠C2AD"),
    "gamma_1": ("the transmission angle γ1", "传动角 γ1"), "gamma_2": ("the transmission angle γ2", "传动角 γ2"),
    "alpha_max_rise": ("the largest pressure angle of the rise αmax", "推程最大压力角 αmax"),
    "delta_alpha_max_rise": ("the cam angle δ where it occurs", "其所在凸轮转角 δ"),
    "alpha_max_return": ("the largest pressure angle of the return α′max", "回程最大压力角 α′max"),
    "delta_alpha_max_return": ("the cam angle δ where it occurs", "其所在凸轮转角 δ"),
    "rho_min_pitch": ("the smallest radius of curvature of the pitch curve ρmin", "理论廓线最小曲率半径 ρmin"),
    "rho_min_actual": ("the smallest radius of curvature of the profile ρa,min", "实际廓线最小曲率半径 ρa,min"),
    "omega2": ("the coupler's angular velocity ω2", "连杆的角速度 ω2"),
    "omega3": ("the rocker's angular velocity ω3", "摇杆的角速度 ω3"),
    "epsilon2": ("the coupler's angular acceleration ε2", "连杆的角加速度 ε2"),
    "epsilon3": ("the rocker's angular acceleration ε3", "摇杆的角加速度 ε3"),
    "vC": ("the velocity of C", "C 点的速度 vC"), "aC": ("the acceleration of C", "C 点的加速度 aC"),
    "vE": ("the velocity of E", "E 点的速度 vE"), "aE": ("the acceleration of E", "E 点的加速度 aE"),
    "v_slip": ("the block's sliding velocity along the guide", "滑块沿导杆的相对速度"),
    "a_slip": ("the block's relative acceleration along the guide", "滑块沿导杆的相对加速度"),
    "a_coriolis": ("the Coriolis acceleration", "哥氏加速度"),
    "vB3": ("the velocity of the guide bar's point B3 under the block", "导杆上与滑块重合点 B3 的速度"),
    "vD": ("the velocity of D", "D 点的速度 vD"), "aD": ("the acceleration of D", "D 点的加速度 aD"),
    "omega4": ("the coupler DE's angular velocity ω4", "连杆 DE 的角速度 ω4"),
    "epsilon4": ("the coupler DE's angular acceleration ε4", "连杆 DE 的角加速度 ε4"),
    "w3_w1": ("the ratio ω3/ω1", "角速度比 ω3/ω1"), "w2_w1": ("the ratio ω2/ω1", "角速度比 ω2/ω1"),
    "i13": ("the transmission ratio i13", "传动比 i13"),
    "vC_w1": ("the slider's velocity per unit crank speed vC/ω1", "滑块速度与曲柄角速度之比 vC/ω1"),
    "v_max": ("the follower's largest speed vmax", "从动件最大速度 vmax"),
    "a_max": ("the follower's largest acceleration amax", "从动件最大加速度 amax"),
    "omega2_max": ("the arm's largest angular speed ω2,max", "摆杆最大角速度 ω2,max"),
    "epsilon2_max": ("the arm's largest angular acceleration ε2,max", "摆杆最大角加速度 ε2,max"),
    "r0": ("the smallest base circle r0", "最小基圆半径 r0"),
}
"""How a statement names an asked answer (English, Chinese); others are named by their answer name."""


AT_WORDS = {"v": ("the follower's velocity v", "从动件速度 v"), "a": ("the follower's acceleration a", "从动件加速度 a"),
            "omega2": ("the arm's angular velocity ω2", "摆杆角速度 ω2"),
            "epsilon2": ("the arm's angular acceleration ε2", "摆杆角加速度 ε2")}
"""How a statement names a list answer at a cam angle of ``at`` (besides s and α)."""


_POSITION_WORDS = {"AB": ("the input link AB", "输入杆长 AB"), "CD": ("the output link CD", "输出杆长 CD")}
RECIPE_WORDS: dict[str, dict[str, tuple[str, str]]] = {
    "four_bar.three_positions": _POSITION_WORDS, "four_bar.three_positions_fixed_pivots": _POSITION_WORDS}
"""A recipe's own words for an answer, before :data:`ANSWER_WORDS`: a linkage designed through given positions
is not known to be a crank-rocker (100-01's AB is a rocker), so its AB and CD are the input and output links."""


def answer_words(name: str, index: int | None, given: Mapping[str, Any], lang: str, recipe: str = "") -> str:
    """How the statement names an asked answer; ``s[i]`` and ``alpha[i]`` name the cam angle ``at[i]``; a
    ``recipe``'s own words (:data:`RECIPE_WORDS`) come first.

    >>> answer_words("s", 1, {"at": [30, 60]}, "en"), answer_words("alpha", 0, {"at": [30]}, "zh")
    ('the displacement s at δ = 60°', 'δ = 30° 时的压力角 α')
    >>> answer_words("boundaries", 1, {"AB": 160}, "en")
    'the 2nd length (from the shortest) at which the type changes'
    """
    k = 1 if lang == "zh" else 0
    if index is not None and name == "boundaries":
        return (f"the {_ordinal(index + 1)} length (from the shortest) at which the type changes",
                f"从小到大第 {index + 1} 个类型改变处的杆长")[k]
    if index is not None:
        at = given.get("at") or ()
        where = f"δ = {number(at[index])}°" if index < len(at) else f"[{index}]"
        if name == "s":
            return (f"the displacement s at {where}", f"{where} 时的位移 s")[k]
        if name == "alpha":
            return (f"the pressure angle α at {where}", f"{where} 时的压力角 α")[k]
        if name in AT_WORDS:
            en, zh = AT_WORDS[name]
            return (f"{en} at {where}", f"{where} 时的{zh}")[k]
        return f"{name} ({where})"
    return (RECIPE_WORDS.get(recipe, {}).get(name) or ANSWER_WORDS.get(name, (name, name)))[k]


def _ordinal(n: int) -> str:
    """1st, 2nd, 3rd, 4th … 11th, 12th, 13th, 21st.

    >>> [_ordinal(n) for n in (1, 2, 3, 4, 11, 12, 13, 21)]
    ['1st', '2nd', '3rd', '4th', '11th', '12th', '13th', '21st']
    """
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def find_sentence(words: list[str], lang: str) -> str:
    """The sentence asking for the answers.

    >>> find_sentence(["the crank AB", "the frame AD"], "en"), find_sentence(["曲柄长 AB"], "zh")
    ('Find the crank AB and the frame AD.', '求曲柄长 AB。')
    """
    if lang == "zh":
        return "求" + "、".join(words) + "。"
    if len(words) == 1:
        return f"Find {words[0]}."
    return "Find " + ", ".join(words[:-1]) + f" and {words[-1]}."


__all__ = ["ANSWER_WORDS", "CHOICE", "CLAUSES", "RECIPE_WORDS", "TEMPLATES", "answer_words", "default_template", "fill", "find_sentence",
           "generic_template", "number", "program_words", "shown_givens", "template_form", "CAM_DRAW", "ROLLER"]
