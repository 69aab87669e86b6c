"""The words of our Chinese texts, so that a line breaks between words, never inside one ("曲\\n柄", "最小传动\\n角",
"滑枕行\\n程" were printed before).

Every Chinese text we print comes from our own templates (the recipes' captions, the results' glosses, the
warnings, the worksheets), so a glossary of their words segments them all: a run of ideographs is cut into the
fewest pieces, each a word of :data:`WORDS` or one character, the longer first word taken on a tie. A word
missing here shows as characters left alone that are not words by themselves (:data:`SINGLE`): a test over
every Chinese text of the gallery asks for it.

A segmentation library would do the same for any text, but jieba (the usual one) is 42 MB, loads its
dictionary in about 1.4 s of CPU in every process that uses it, writes a cache file to the temp directory, and
cuts our mechanism words wrongly all the same (导路 → 导 路, 从动件 → 从 动 件, 作曲柄圆 → 作曲 柄 圆, 凸轮廓线 →
凸 轮廓线) unless it is given this very glossary.

Examples
--------
>>> words("作曲柄圆交摇杆圆于")
('作', '曲柄', '圆', '交', '摇杆', '圆', '于')
>>> words("凸轮廓线"), words("取摇杆长等于机架长")
(('凸轮', '廓线'), ('取', '摇杆', '长', '等于', '机架', '长'))
"""
from __future__ import annotations

import functools

_LONGEST = 6

WORDS = frozenset("""
曲柄 摇杆 连杆 机架 滑块 导杆 导路 摆杆 滑枕 刨头 构件 主动件 从动件 输入件 连架杆 摇臂 铰链 机构 凸轮 滚子 平底 尖顶
四杆 两杆 杆长 臂长 周转副 摆转副 转动副 高副 低代 直动 盘形 圆盘 变点 死点 瞬心 三心 定理 哥氏 科氏
基圆 廓线 轮廓 理论 实际 偏距 偏置 对心 等长 中心 中心线 中心距 中垂线 中点 圆心 圆弧 弧段 半径 直径 外接圆 三角形 多边形 包络线
直线 射线 曲线 切线 法线 公法线 垂线 垂足 垂直 垂直于 平行 平行于 平行线 延长 延长线 水平 水平线 铅垂 铅垂线 竖直 连线
交点 切点 端点 原点 极点 接触点 对称点 最低点 最高点 标线 方向线 纵坐标 纵轴 转轴 有向 夹角 倾角 凸角 锐角 直角 张角
压力 压力角 传动 传动角 传动比 摆角 转角 运动角 休止角 极位夹角 行程 推程 回程 空回 行程速比系数 速比 系数
位移 位置 速度 角速度 加速度 角加速度 曲率 比例 比例尺 线图 长度 宽度 高度 距离 余量 上限 弓高 跃度 正值 误差 精度 答案
极限 共线 重叠 拉直 折叠 重合 相交 相切 相对 相同 相差 相距 分支 装配 可行 可行域 边界 范围 条件 类型 规律 原理 影像 导数 解析
刚性 刚化 冲击 突降 失真 根切 磨损 接触应力 错位 缺陷 敏感度 存疑 教材 作图 正弦 多解 等号 反转 反转法 逆转
运动 转动 摆动 移动 滑动 平移 回转 周转 整周 全周 一周 逆时针 顺时针 方向 方位 转向 指向 向上 背离 远离 偏离 偏移
作出 画出 求得 量得 量取 截取 截去 等分 分点 平分 标注 标记 绘制 复制 缩放 选定 搜索 判断 决定 限制 保持 满足 存在
达到 到达 经过 通过 超过 超出 直至 移至 连接 连续 连成 光滑 推动 受力 作用 起作用 设计 输入 输出 逐点 改变 增大 减小 错误 因而 释义 右偏 左偏 顺转
许用 轨迹 反向 分段 接触 试用 小于 高于 等于 异于 对应 关于 位于 处于 之间 之外 之下 之和 之比 所在 所得 所求 所指 候选 备选 初始 起始 起止 终点
最大 最小 最长 最短 最低 最高 最近 最远 最佳 上方 下方 左侧 右侧 一侧 另一侧 外侧 同侧 两端 该处 无穷 无穷远
一个 两个 三个 一点 一致 一系列 第一 第二 同一 另一 二者 两圆 两线 不同 不是 不能 不在 全部 其余 其间 其中 此时 否则
分别 同理 如图 已知 精确 正确 慢速 工作 居中 比较 外凸 活动 固定 箭头 顺序 休止 详见 任何
唯一 其他 覆盖 始终 足以
各种 颚式 破碎机 颚板 保留 改为 升程 等速 等加速 等减速 余弦 偏心 偏心圆 多项式 相反 表格 给出 实测 斜率 给定 三次 样条
驱动 图示 急回 惠特沃斯
""".split())
"""Words of two characters or more (at most :data:`_LONGEST`) that a line never breaks inside."""

SINGLE = frozenset("""
故 应 此 加 并 的 之 其 该 每 各 者 所 为 是 与 及 或 且 若 即 于 在 以 由 按 沿 绕 自 至 到 向 过 对 离 经 将 把 被 随 使 须 能 可 不
仍 仅 只 再 均 任 另 同 一 两 双 六 第 上 中 内 后 旁 边 侧 处 时 近 远 较 高 短 小 慢 正 逆 顺 非 否 无 有 用 夹
作 取 交 画 求 得 量 成 转 找 见 切 张 个 靠 带 标 点 线 圆 弧 弦 角 杆 长 距 轴 销 族 值 解 根
""".split())
"""Characters that are words by themselves (particles, prepositions, measure and function words, single-syllable
verbs and nouns of a construction: 以 A 为圆心, 作圆, 交于, 取点): a character of a text that is neither one nor part
of a word of :data:`WORDS` is a word the glossary is missing."""


@functools.lru_cache(maxsize=4096)
def words(run: str) -> tuple[str, ...]:
    """A run of Chinese ideographs cut into the fewest pieces, each a word of :data:`WORDS` or one character; of
    cuts into as many pieces, the one whose first piece is longest (then its second, …).

    >>> words("第一固定铰链处的连架杆为曲柄")
    ('第一', '固定', '铰链', '处', '的', '连架杆', '为', '曲柄')
    >>> words("按行程速比系数"), words("")
    (('按', '行程速比系数'), ())
    """
    n = len(run)
    best = [0] * (n + 1)            # best[i]: fewest pieces of run[i:]
    step = [1] * (n + 1)            # step[i]: the length of its first piece
    for i in range(n - 1, -1, -1):
        best[i] = n + 1
        for k in range(min(_LONGEST, n - i), 0, -1):         # the longest first on a tie
            if (k == 1 or run[i:i + k] in WORDS) and best[i + k] + 1 < best[i]:
                best[i], step[i] = best[i + k] + 1, k
    out, i = [], 0
    while i < n:
        out.append(run[i:i + step[i]])
        i += step[i]
    return tuple(out)


def is_ideograph(ch: str) -> bool:
    """Whether ``ch`` is a Chinese ideograph (a character a word of :data:`WORDS` is made of)."""
    return "\u3400" <= ch <= "\u9fff" or "\uf900" <= ch <= "\ufaff"


__all__ = ["SINGLE", "WORDS", "is_ideograph", "words"]
