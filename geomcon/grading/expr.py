"""A teacher's diagnosis as an expression of other answers and givens: a tiny arithmetic grammar, parsed
here (never ``eval``).

Grammar::

    expr   := term (("+" | "-") term)*
    term   := factor (("*" | "/") factor)*
    factor := ("+" | "-") factor | power
    power  := atom ("^" factor)?
    atom   := NUMBER | NAME | NAME "(" expr ")" | "(" expr ")"

NAME is an answer or a given of the exercise (``AB``, ``theta``, ``s[0]``) or ``pi``; the functions are
``sqrt abs sin cos tan asin acos atan`` with angles in degrees, as everywhere in geomcon. An expression is at
most 200 characters and 64 tokens; an unknown name, a stray character or a division by zero is an error
naming the expression.

Examples
--------
>>> e = parse("BC + AB")
>>> e.names, e({"AB": 20.0, "BC": 60.0})
(('AB', 'BC'), 80.0)
>>> parse("2*sin(30) - -1")({})
2.0
>>> parse("__import__('os')")
Traceback (most recent call last):
...
ValueError: expression "__import__('os')": unexpected character "'" at 11
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any, Callable, Mapping

MAX_CHARS = 200
MAX_TOKENS = 64
_TOKEN = re.compile(r"\s*(?:(\d+(?:\.\d*)?(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|([A-Za-z_][A-Za-z0-9_]*(?:\[\d{1,3}\])?)"
                    r"|(\*\*|[-+*/^()]))")
_FUNCS: dict[str, Callable[[float], float]] = {
    "sqrt": math.sqrt, "abs": abs,
    "sin": lambda x: math.sin(math.radians(x)), "cos": lambda x: math.cos(math.radians(x)),
    "tan": lambda x: math.tan(math.radians(x)), "asin": lambda x: math.degrees(math.asin(x)),
    "acos": lambda x: math.degrees(math.acos(x)), "atan": lambda x: math.degrees(math.atan(x)),
}


@dataclass(frozen=True)
class Expr:
    """A parsed expression: call it with the values of its ``names``."""

    text: str
    tree: Any
    names: tuple[str, ...]

    def __call__(self, values: Mapping[str, float]) -> float:
        try:
            return float(_eval(self.tree, values))
        except (ZeroDivisionError, ValueError, OverflowError) as exc:
            raise ValueError(f"expression {self.text!r}: {exc}") from None


def _eval(t: Any, v: Mapping[str, float]) -> float:
    kind = t[0]
    if kind == "num":
        return t[1]
    if kind == "name":
        return math.pi if t[1] == "pi" else float(v[t[1]])
    if kind == "neg":
        return -_eval(t[1], v)
    if kind == "call":
        return _FUNCS[t[1]](_eval(t[2], v))
    a, b = _eval(t[1], v), _eval(t[2], v)
    if kind == "+":
        return a + b
    if kind == "-":
        return a - b
    if kind == "*":
        return a * b
    if kind == "/":
        return a / b
    return a ** b


def _tokens(text: str) -> list[tuple[str, Any, int]]:
    out, pos = [], 0
    while pos < len(text):
        if text[pos:].strip() == "":
            break
        m = _TOKEN.match(text, pos)
        if m is None:
            at = pos + len(text[pos:]) - len(text[pos:].lstrip())
            raise ValueError(f"expression {text!r}: unexpected character \"{text[at]}\" at {at}")
        num, name, op = m.groups()
        out.append(("num", float(num), m.start()) if num else ("name", name, m.start()) if name
                   else ("op", "^" if op == "**" else op, m.start()))
        pos = m.end()
        if len(out) > MAX_TOKENS:
            raise ValueError(f"expression {text!r}: more than {MAX_TOKENS} tokens")
    return out


def parse(text: str, names: set[str] | None = None) -> Expr:
    """Parse ``text``; with ``names``, every name it uses must be one of them (or a function, or ``pi``).

    Raises
    ------
    ValueError
        A syntax error, an unknown name or an over-long expression, naming the expression.
    """
    if not isinstance(text, str) or len(text) > MAX_CHARS:
        raise ValueError(f"an expression must be a text of at most {MAX_CHARS} characters")
    toks = _tokens(text)
    pos = 0
    used: list[str] = []

    def peek() -> tuple[str, Any, int] | None:
        return toks[pos] if pos < len(toks) else None

    def take(op: str | None = None) -> tuple[str, Any, int]:
        nonlocal pos
        t = peek()
        if t is None or (op is not None and t[1] != op):
            raise ValueError(f"expression {text!r}: expected {op or 'a value'} "
                             + (f"at {t[2]}" if t else "at the end"))
        pos += 1
        return t

    def chain(operand, ops: str) -> Any:
        """``operand (op operand)*`` for the operators ``ops``, left-associative."""
        left = operand()
        while (t := peek()) and t[0] == "op" and t[1] in ops:
            take()
            left = (t[1], left, operand())
        return left

    def expr() -> Any:
        return chain(term, "+-")

    def term() -> Any:
        return chain(factor, "*/")

    def factor() -> Any:
        t = peek()
        if t and t[0] == "op" and t[1] in "+-":
            take()
            inner = factor()
            return ("neg", inner) if t[1] == "-" else inner
        base = atom()
        if (t := peek()) and t[0] == "op" and t[1] == "^":
            take()
            return ("^", base, factor())
        return base

    def atom() -> Any:
        t = take()
        if t[0] == "num":
            return ("num", t[1])
        if t[0] == "name":
            nxt = peek()
            if nxt and nxt[1] == "(" and t[1] in _FUNCS:
                take("(")
                inner = expr()
                take(")")
                return ("call", t[1], inner)
            if t[1] != "pi":
                if names is not None and t[1] not in names:
                    raise ValueError(f"expression {text!r}: unknown name {t[1]!r} "
                                     f"(names: {', '.join(sorted(names))})")
                used.append(t[1])
            return ("name", t[1])
        if t[1] == "(":
            inner = expr()
            take(")")
            return inner
        raise ValueError(f"expression {text!r}: unexpected {t[1]!r} at {t[2]}")

    tree = expr()
    if peek() is not None:
        raise ValueError(f"expression {text!r}: unexpected {peek()[1]!r} at {peek()[2]}")
    return Expr(text, tree, tuple(sorted(set(used))))


__all__ = ["Expr", "MAX_CHARS", "MAX_TOKENS", "parse"]
