"""Warnings in Chinese: each warning geomcon writes (a recipe's borderline geometry, a failed or ill-conditioned
check, a printed answer that is doubtful, α beyond its allowance, a branch defect, an undercut …) has one rule
here, a pattern over its English sentence and the Chinese sentence with the same numbers, so that a figure, a
player and a print sheet drawn with ``--lang zh`` or ``both`` say it in Chinese (full-width punctuation).

The English sentence stays the warning's identity (JSON ``warnings`` is a contract and keeps it); a sentence no
rule knows is shown in English. ``tests/test_warning_words.py`` checks that every rule has an example it
translates, and that every warning of the bundled problems is translated.

Examples
--------
>>> warning_zh("α_max of the return = 36.71° exceeds alpha_allow = 30° (at δ = 230.3°)")
'回程最大压力角 αmax = 36.71° 超过许用压力角 alpha_allow = 30°（δ = 230.3° 处）'
>>> warning_lines(["published theta = 25 is doubtful: it deviates from the exact 12.5056 by +99.91 %, beyond "
...                "drafting accuracy (±3 %)"], "zh")
['教材答案 θ = 25 存疑：与精确值 12.5056 相差 +99.91 %，超出作图精度（±3 %）']
>>> warning_zh("a sentence no rule knows") is None
True
"""
from __future__ import annotations

import re
from typing import Callable, Mapping, Sequence

from .zh import zh_brackets, zh_punct

PART = {"rise": "推程", "return": "回程"}
"""A cam's part of the motion."""

WHAT = {"the fixed pivot A": "固定铰链 A", "the fixed pivot D": "固定铰链 D", "the hinge C1": "铰链 C1",
        "the hinge F1": "铰链 F1", "C1": "C1", "F1": "F1", "the coupler is not rigid": "连杆不是刚体",
        "the input link does not keep its length": "输入连架杆长度不一致",
        "K is not one point of a rigid coupler": "K 不是刚性连杆上的同一点", "side of C from B→D": "C 在 B→D 的哪一侧",
        "pin E against the foot of F on the guide": "销 E 相对 F 在导路上的垂足"}
"""The phrases a warning takes from its recipe (what moves, what is wrong), in Chinese."""

WHY = {"(drafted data?): each C_i is slid along B_iC_i to the mean BC = ": "（作图数据？）：各 C_i 沿 B_iC_i 移到平均值 BC = ",
       "(drafted data?): each B_i is slid along AB_i to the mean AB = ": "（作图数据？）：各 B_i 沿 AB_i 移到平均值 AB = ",
       "(drafting error?): only the directions B_iK_i, the coupler's angles, are used":
           "（作图误差？）：只用 B_iK_i 的方向，即连杆的转角"}


def _what(s: str) -> str:
    return WHAT.get(s, s)


def _why(s: str) -> str:
    for en, zh in WHY.items():
        if s.startswith(en):
            rest = s[len(en):].replace(" mm, K_i with it", " mm，K_i 随之移动")
            return zh + rest
    return s


def _sides(s: str | None) -> str:
    """Which side of a line each position's point lies on, in Chinese (``C1 left, C3 right``,
    ``position 1: left``).

    >>> _sides("C1 left, C2 left, C3 right"), _sides("position 1: left, position 2: on it")
    ('C1 左侧、C2 左侧、C3 右侧', '位置 1：左侧、位置 2：线上')
    """
    s = re.sub(r"position (\d+): ", r"位置 \1：", s or "")
    for en, zh in ((" left", " 左侧"), (" right", " 右侧"), (" on it", " 线上"), ("：left", "：左侧"),
                   ("：right", "：右侧"), ("：on it", "：线上"), ("：ahead", "：在前"), ("：behind", "：在后"),
                   ("：at it", "：重合"), (", ", "、")):
        s = s.replace(en, zh)
    return s


def _solution(s: str | None) -> str:
    m = re.fullmatch(r"solution (\d+): ", s or "")
    return f"解 {m.group(1)}：" if m else ""


def _opt(zh: str) -> Callable[[str | None], str]:
    """A part of the sentence that is there only when its group matched."""
    return lambda s: zh if s else ""


Rule = tuple[str, str, Mapping[str, Callable[[str | None], str]]]

RULES: tuple[Rule, ...] = (
    (r"published (?P<q>\S+) = (?P<p>\S+) is doubtful: it deviates from the exact (?P<e>\S+) by (?P<how>.+?), "
     r"beyond drafting accuracy \(±(?P<acc>.+?)\)",
     "教材答案 {q} = {p} 存疑：与精确值 {e} 相差 {how}，超出作图精度（±{acc}）", {}),
    (r"(?P<which>solution \d+: )?γmin = (?P<g>\S+)° is below gamma_allow = (?P<a>\S+)°",
     "{which}最小传动角 γmin = {g}° 小于许用传动角 gamma_allow = {a}°", {"which": _solution}),
    (r"check failed: (?P<q>\S+) construction (?P<a>.+?) vs analytic (?P<b>.+)",
     "校核失败：{q} 的作图值 {a} 与解析值 {b} 不符", {}),
    (r"(?P<q>\S+): construction (?P<a>.+?), analytic (?P<b>.+?) — the data lie on the boundary where it changes "
     r"\(it flips within a relative change of (?P<s>\S+)\)",
     "{q}：作图值 {a}，解析值 {b}——数据正处于其改变的边界上（给定值相对变化 {s} 之内即改变）", {}),
    (r"(?P<q>\S+) is ill-conditioned: it moves (?P<k>\S+) times the relative change of the givens; construction "
     r"and twin agree to (?P<e>\S+) \(allowed (?P<t>\S+)\)",
     "{q} 为病态问题：其相对变化是给定值相对变化的 {k} 倍；作图与解析解相差 {e}（允许 {t}）", {}),
    (r"α_max of the (?P<part>rise|return) = (?P<a>\S+)° exceeds alpha_allow = (?P<b>\S+)° \(at δ = (?P<d>\S+)°\)",
     "{part}最大压力角 αmax = {a}° 超过许用压力角 alpha_allow = {b}°（δ = {d}° 处）", {"part": PART.get}),
    (r"α_max of the (?P<part>rise|return) = (?P<a>\S+)° exceeds the allowance (?P<b>\S+)° \(at δ = (?P<d>\S+)°\)",
     "{part}最大压力角 αmax = {a}° 超过许用值 {b}°（δ = {d}° 处）", {"part": PART.get}),
    (r"undercut: rr = (?P<r>\S+) ≥ ρmin = (?P<p>\S+) of the pitch curve(?P<at> \(at δ = (?P<d>\S+)°\))?; the profile "
     r"is trimmed and the follower's motion is distorted there \(增大基圆或减小滚子半径\)",
     "运动失真（根切）：滚子半径 rr = {r} ≥ 理论廓线最小曲率半径 ρmin = {p}{at}；实际廓线被截去，从动件的运动在该处失真"
     "（增大基圆或减小滚子半径）", {"at": lambda s: f"（{s.strip()[4:-1]} 处）" if s else ""}),
    (r"ρmin = (?P<p>\S+) of the pitch curve is below (?P<k>\S+)·rr = (?P<v>\S+): the actual profile's ρa = (?P<q>\S+) "
     r"is small \(wear, contact stress\)",
     "理论廓线最小曲率半径 ρmin = {p} 小于 {k}·rr = {v}：实际廓线的 ρa = {q} 过小（磨损、接触应力）", {}),
    (r"the pitch curve has a convex corner at δ = (?P<d>.+?) \(velocity drop, rigid impact\)"
     r"(?P<roller>: the roller cannot follow it exactly there)?",
     "理论廓线在 δ = {d} 处有凸角（速度突降，刚性冲击）{roller}", {"roller": _opt("：滚子在该处不能准确跟随")}),
    (r"the flat face cannot follow the motion: min\(r0 \+ s \+ s″\) = (?P<x>\S+?)"
     r"(?P<drop> and the velocity drops suddenly \(s′ jumps down\))?; the profile is trimmed \(增大基圆 r0\)",
     "平底从动件不能实现该运动：min(r0 + s + s″) = {x}{drop}；廓线被截去（增大基圆 r0）",
     {"drop": _opt("，且速度突降（s′ 向下跳变）")}),
    (r"the flat face cannot follow the motion: ρmin of the profile = (?P<x>\S+) mm at δ = (?P<d>\S+)°"
     r"(?:; the contact jumps back along the face at δ = (?P<b>.+?) \(ψ′ drops suddenly\))?; the profile is trimmed "
     r"\(增大基圆 r0\)",
     "平底从动件不能实现该运动：δ = {d}° 处廓线最小曲率半径 ρmin = {x} mm{b}；廓线被截去（增大基圆 r0）",
     {"b": lambda s: f"；δ = {s} 处接触点沿平底向回跳（ψ′ 突降）" if s else ""}),
    (r"the profile reaches about (?P<x>\S+) mm from O, beyond the arm's pivot \(a = (?P<a>\S+)\): it would hit the "
     r"pivot", "廓线离 O 约 {x} mm，超过摆杆转轴（a = {a}）：将与转轴相碰", {}),
    (r"the cam reaches (?P<x>\S+) mm from O at the top of the stroke, beyond the arm's pivot \(a = (?P<a>\S+)\): it "
     r"would hit the pivot", "行程最高点处凸轮离 O {x} mm，超过摆杆转轴（a = {a}）：将与转轴相碰", {}),
    (r"branch defect: the three positions are not on one assembly branch \(C on different sides of B→D: (?P<s>.+?)\); "
     r"no continuous motion of the linkage passes all three",
     "错位缺陷：三个位置不在同一装配分支上（C 位于 B→D 的不同侧：{s}）；机构不能连续运动经过全部三个位置", {"s": _sides}),
    (r"branch defect: the designed positions lie on different assembly branches \((?P<w>.+?): (?P<x>.+?)\); they "
     r"cannot all be reached without taking the linkage apart",
     "错位缺陷：设计位置位于不同的装配分支上（{w}：{x}）；不拆开机构便不能全部到达", {"w": _what, "x": _sides}),
    (r"order defect: the input meets a dead point turning from B1 through B2 to B3 \(crank angles (?P<l>.+?); AB is "
     r"not a crank\), so the positions are not reached in the given order by one motion",
     "错序缺陷：输入构件由 B1 经 B2 转到 B3 时遇到死点（曲柄转角 {l}；AB 不是曲柄），一次运动不能按给定顺序到达各位置", {}),
    (r"order defect: the input's motion from position 1 through 2 to 3 passes a dead point \(γ = 0 at (?P<x>.+?)\); "
     r"the positions are not reached in the given order",
     "错序缺陷：输入构件由位置 1 经 2 到 3 的运动经过死点（{x} 处 γ = 0）；不能按给定顺序到达各位置", {}),
    (r"Grashof equality s \+ l = p \+ q: a change-point linkage \(all links can be collinear\)",
     "杆长条件取等号 s + l = p + q：变点机构（各杆可共线）", {}),
    (r"Grashof equality s \+ l = p \+ q = (?P<x>\S+): a change-point chain \(the links can all be collinear, γ = 0 "
     r"there\)", "杆长条件取等号 s + l = p + q = {x}：变点机构（各杆可全部共线，此时 γ = 0）", {}),
    (r"Grashof equality (?P<e>.+?) = (?P<x>\S+): a change-point linkage \(links can all be collinear, γmin = 0\)",
     "杆长条件取等号 {e} = {x}：变点机构（各杆可共线，γmin = 0）", {}),
    (r"the longest link (?P<x>\S+) ≥ the sum of the other three (?P<y>\S+): the chain cannot move \(immovable\)",
     "最长杆 {x} ≥ 其余三杆之和 {y}：机构不能运动", {}),
    (r"AB \+ e = BC = (?P<x>\S+): the rod is perpendicular to the guide at one position \(αmax = 90°\)",
     "AB + e = BC = {x}：连杆在某一位置垂直于导路（αmax = 90°）", {}),
    (r"(?P<w>\S+) = (?P<x>\S+) is at the end Q of the admissible arc: AB \+ e = BC, αmax = 90°",
     "{w} = {x} 位于许用圆弧的端点 Q：AB + e = BC，αmax = 90°", {}),
    (r"(?P<seq>.+?) are nearly collinear: R/h_min = (?P<k>\S+) ≥ (?P<w>\S+), (?P<what>.+?) moves up to (?P<x>\S+) mm "
     r"per (?P<d>\S+) mm of drafting error",
     "{seq} 近于共线：R/h_min = {k} ≥ {w}，作图误差每 {d} mm 使{what}最多移动 {x} mm", {"what": _what}),
    (r"the inverted points (?P<n>.+?) are nearly collinear \(R/h_min = (?P<k>\S+) ≥ (?P<w>\S+)\): (?P<what>.+?) moves "
     r"up to (?P<x>\S+) mm per mm of error in one of them",
     "反转后的点 {n} 近于共线（R/h_min = {k} ≥ {w}）：其中一点每 1 mm 误差使 {what} 最多移动 {x} mm", {"what": _what}),
    (r"the bisector of F1F2′ meets the guide far away \((?P<where>.+?)\): E1 moves up to (?P<x>\S+) mm per mm of "
     r"drafting error \(≥ (?P<w>\S+)\)",
     "F1F2′ 的中垂线与导路的交点很远（{where}）：作图误差每 1 mm 使 E1 最多移动 {x} mm（≥ {w}）", {}),
    (r"'(?P<q>.+?)' has (?P<n>\d+) extremes per turn: K is not defined \(stroke = largest maximum − smallest "
     r"minimum\)", "{q} 每转有 {n} 个极值：K 无定义（行程 = 最大的极大值 − 最小的极小值）", {}),
    (r"printed (?P<k>\S+) = (?P<v>\S+) is off the exact (?P<x>\S+)", "教材答案 {k} = {v} 与精确值 {x} 不符", {}),
    (r"offset on the wrong side: e = (?P<e>\S+) puts the follower's axis (?P<side>left|right) of O on a (?P<rot>ccw|cw) "
     r"cam, which makes the rise's pressure angles larger \(a ccw cam wants the axis right of O, a cw cam left\)",
     "偏置方位错误：e = {e}，凸轮{rot}转动时导路在 O {side}，推程压力角因而增大（应逆转右偏、顺转左偏）",
     {"side": {"left": "左侧", "right": "右侧"}.get, "rot": {"ccw": "逆时针", "cw": "顺时针"}.get}),
    (r"(?P<what>the coupler is not rigid|the input link does not keep its length|K is not one point of a rigid "
     r"coupler): (?P<seq>.+?) differ by (?P<s>\S+) mm(?P<why> .*)?",
     "{what}：{seq} 相差 {s} mm{why}", {"what": _what, "why": lambda s: _why(s.strip()) if s else ""}),
)
"""(English pattern, Chinese sentence, how a group is translated): the whole warning must match."""

_COMPILED = tuple((re.compile(p), zh, fns) for p, zh, fns in RULES)


def warning_zh(warning: str) -> str | None:
    """The Chinese sentence of an English warning (full-width punctuation), or None when no rule knows it."""
    for pattern, zh, fns in _COMPILED:
        m = pattern.fullmatch(warning)
        if m:
            groups = {k: (fns[k](v) if k in fns else (v or "")) for k, v in m.groupdict().items()}
            return zh_punct(zh.format(**groups))
    return None


_GIVEN_SYMBOLS = {"gamma_allow": ("γ_allow", "[γ]"), "alpha_allow": ("α_allow", "[α]")}
"""A given a warning names by its problem-file key, as a figure prints it (English: γ with the subscript allow;
Chinese: the textbook's [γ])."""
_RETURN_ALPHA = (("α_max of the return", "α′_max of the return"), ("回程最大压力角 αmax", "回程最大压力角 α′max"))
"""The return's largest pressure angle as the Results block prints it: α′max (a primed α, subscript max)."""
_AUDITED = re.compile(r"(?<=^published )(\w+)(\[\d+\])?|(?<=^教材答案 )(\w+)(\[\d+\])?")


def printed_words(line: str, zh: bool = False, at: Mapping[str, Sequence[float]] | None = None) -> str:
    """A warning line with the identifiers it quotes written as the figure's Results block prints them: an audited
    answer by its symbol (``theta`` → ``θ``; ``profile_x[0]`` → ``xa[0] (profile points)``, the return's α_max as α′_max) and a given allowance
    by its symbol (``alpha_allow`` → ``α_allow``, drawn as α with a subscript; ``[α]`` in Chinese).

    >>> printed_words("published profile_x[0] = -26.8 is doubtful")
    'published xa[0] (profile points) = -26.8 is doubtful'
    >>> printed_words("回程最大压力角 αmax = 36.71° 超过许用压力角 alpha_allow = 30°", zh=True)
    '回程最大压力角 α′max = 36.71° 超过许用压力角 [α] = 30°'

    A list's entry is named as its Results line names it (:func:`~geomcon.render.results.entries`; ``at``: the
    cam angles of the list answers given at angles, by answer):

    >>> printed_words("published psi[2] = 14.4 is doubtful", at={"psi": (2, 4, 6, 8, 10)})
    'published ψ(6°) (swing of the arm) = 14.4 is doubtful'
    """
    from .results import entries, name_of

    def answer(m: re.Match) -> str:
        key, index = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
        name = name_of(key)
        if not name.symbol or name.symbol == key.replace("_", " "):
            return m.group(0)
        words = name.zh if zh else name.en
        head = entries(name.symbol, [int(index[1:-1])], (at or {}).get(key, ())) if index else name.symbol
        return head + (f"（{words}）" if zh else f" ({words})") * bool(index and words)

    line = _AUDITED.sub(answer, line)
    for raw, primed in _RETURN_ALPHA:                        # the return's angle is α′, as the Results print it
        line = line.replace(raw, primed)
    for key, (en, zh_form) in _GIVEN_SYMBOLS.items():
        line = line.replace(key, zh_form if zh else en)
    return line


EN_HINTS = {"(增大基圆或减小滚子半径)": "(enlarge the base circle or use a smaller roller)",
            "(增大基圆 r0)": "(enlarge the base circle r0)"}
"""The Chinese remedy a warning's sentence carries (JSON keeps the sentence as it is), in the words an English
line of a figure prints: an English reader is not left with Chinese, and ``both`` does not print the hint twice
in Chinese."""


def english_words(warning: str) -> str:
    """A warning as a figure's English line prints it: the Chinese remedy it carries in English
    (:data:`EN_HINTS`).

    >>> english_words("undercut: rr = 20 ≥ ρmin = 17.11 of the pitch curve; the profile is trimmed and the "
    ...               "follower's motion is distorted there (增大基圆或减小滚子半径)").split("; ")[1]
    "the profile is trimmed and the follower's motion is distorted there (enlarge the base circle or use a smaller roller)"
    """
    for zh, en in EN_HINTS.items():
        warning = warning.replace(zh, en)
    return warning


def warning_lines(warnings: Sequence[str], lang: str, at: Mapping[str, Sequence[float]] | None = None) -> list[str]:
    """The warnings as a figure prints them: English (``en``), Chinese (``zh``; a warning no rule knows stays in
    English), or each in English followed by its Chinese (``both``); the identifiers they quote as the Results
    block prints them (:func:`printed_words`, ``at`` passed on)."""
    out = []
    for w in warnings:
        zh = warning_zh(w)
        en = zh_brackets(printed_words(english_words(w), at=at))    # a Chinese hint no rule words: （…）
        if lang == "en" or zh is None:
            out.append(en)
        elif lang == "zh":
            out.append(printed_words(zh, zh=True, at=at))
        else:
            out += [en, printed_words(zh, zh=True, at=at)]
    return out


__all__ = ["EN_HINTS", "RULES", "english_words", "printed_words", "warning_lines", "warning_zh"]
