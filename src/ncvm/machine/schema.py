"""A small declarative schema: typed field specs from which the machine-file checks, the reference
tables of docs/machine-file.md and the JSON Schema for editors are all derived, so they cannot drift.

A schema is a tree of nodes (:class:`Number`, :class:`Text`, :class:`Flag`, :class:`ListOf`,
:class:`Table`, :class:`Either`, :class:`Tagged`); a :class:`Table` lists its keys as :class:`Field` s
(name, type, unit, default, doc). :func:`validate` walks a parsed TOML value and raises
:class:`SchemaError` naming the key path, the value and what is wrong. Every number must be finite.
"""

from __future__ import annotations

import math
import re
from typing import Any, Callable

from ..records import FrozenRecord


class SchemaError(Exception):
    """A value that breaks the schema: ``path = value: why``."""

    def __init__(self, path: str, value: Any, why: str):
        super().__init__(f"{path} = {show(value)}: {why}" if value is not MISSING else f"{path}: {why}")
        self.path, self.value, self.why = path, value, why


class _Missing:
    def __repr__(self) -> str:
        return "MISSING"


class Said(str):
    """A default described in words ("all 0", "the [[axis]] list") rather than given as a value."""


MISSING: Any = _Missing()  # a required key the file leaves out (the error shows no value)
NO_DEFAULT: Any = _Missing()


def show(value: Any, depth: int = 2, width: int = 60) -> str:
    """A short TOML-like rendering of ``value`` for a message (bounded, also for absurdly nested input)."""
    if isinstance(value, bool):
        text = "true" if value else "false"
    elif isinstance(value, float):
        text = "nan" if math.isnan(value) else ("inf" if value == math.inf else "-inf" if value == -math.inf
                                                else repr(value))
    elif isinstance(value, str):
        text = '"' + value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    elif isinstance(value, list):
        inner = ", ".join(show(v, depth - 1, width) for v in value[:8]) if depth > 0 else "..."
        text = f"[{inner}{', ...' if len(value) > 8 and depth > 0 else ''}]"
    elif isinstance(value, dict):
        items = list(value.items())
        inner = ", ".join(f"{_key(k)} = {show(v, depth - 1, width)}" for k, v in items[:6]) if depth > 0 else "..."
        text = f"{{ {inner}{', ...' if len(items) > 6 and depth > 0 else ''} }}" if items else "{}"
    else:
        text = str(value)  # int, date/time
    return text if len(text) <= width else text[: width - 3] + "..."


def _key(k: str) -> str:
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else show(k)


def join(path: str, key: str | int) -> str:
    if isinstance(key, int):
        return f"{path}[{key}]"
    return f"{path}.{_key(key)}" if path else _key(key)


class Ctx(FrozenRecord):
    """What checks may refer to besides the value itself: the machine's axes."""

    __slots__ = ("axis_names", "axis_limits")

    def __init__(self, axis_names: tuple[str, ...] = (), axis_limits: tuple[tuple[float, float], ...] = ()):
        self.axis_names = axis_names
        self.axis_limits = axis_limits


class Node(FrozenRecord):
    """One type of value. Subclasses say what they accept, how docs name it, and its JSON Schema."""

    __slots__ = ()

    def check(self, value: Any, path: str, ctx: Ctx) -> None:
        raise NotImplementedError

    def type_text(self) -> str:
        raise NotImplementedError

    def rule_text(self) -> str:
        return ""

    def json(self) -> dict:
        raise NotImplementedError


def _kind(value: Any) -> str:
    return {bool: "a boolean", int: "an integer", float: "a number", str: "a string", list: "an array",
            dict: "a table"}.get(type(value), type(value).__name__)


#: the largest magnitude of any number in a machine file: beyond every machine, and far enough from the
#: float range that sums, squares and offsets of such values stay finite (1e308 made NaN cycle times)
LIMIT = 1e15
#: the least value of a quantity that must be positive: rates, accelerations and ticks are divided by,
#: and 5e-324 made the block times infinite
TINY = 1e-9


class Number(Node):
    """A finite number within +-LIMIT; ``integer`` refuses 2.5 and 2.0 alike (TOML keeps the difference).
    ``gt=0`` ("positive") means at least TINY."""

    __slots__ = ("integer", "min", "max", "gt", "choices")

    def __init__(self, integer: bool = False,
                 min: float | None = None, max: float | None = None, gt: float | None = None,
                 choices: tuple[float, ...] = ()):
        self.integer = integer
        self.min = min  # inclusive bounds
        self.max = max
        self.gt = gt  # exclusive lower bound ("positive": gt=0)
        self.choices = choices

    def check(self, value, path, ctx):
        ok = isinstance(value, int) if self.integer else isinstance(value, (int, float))
        if isinstance(value, bool) or not ok:
            raise SchemaError(path, value, f"must be {self.type_text()}, not {_kind(value)}")
        if isinstance(value, float) and not math.isfinite(value):
            raise SchemaError(path, value, "must be a finite number (NaN and infinity are not allowed)")
        rule = self.rule_text()
        if self.choices and value not in self.choices:
            raise SchemaError(path, value, f"must be {rule}")
        if self.gt is not None and not value > self.gt or self.min is not None and value < self.min \
                or self.max is not None and value > self.max:
            raise SchemaError(path, value, f"must be {rule}")
        if abs(value) > LIMIT:
            raise SchemaError(path, value, f"must lie between {-LIMIT:g} and {LIMIT:g}")
        if self.gt == 0 and 0 < value < TINY:
            raise SchemaError(path, value, f"must be positive and at least {TINY:g}")

    def type_text(self):
        return "an integer" if self.integer else "a number"

    def rule_text(self):
        if self.choices:
            return "one of " + ", ".join(map(_num, self.choices))
        lo = f"> {_num(self.gt)}" if self.gt is not None else f">= {_num(self.min)}" if self.min is not None else ""
        if self.max is None:
            return {"> 0": "positive", ">= 0": "zero or positive"}.get(lo, lo)
        if self.min is not None:
            return f"{_num(self.min)} to {_num(self.max)}"
        return f"{lo} and <= {_num(self.max)}" if lo else f"<= {_num(self.max)}"

    def json(self):
        out: dict = {"type": "integer" if self.integer else "number"}
        if self.choices:
            out["enum"] = list(self.choices)
        if self.gt == 0:
            out["minimum"] = TINY
        elif self.gt is not None:
            out["exclusiveMinimum"] = self.gt
        out["minimum"] = self.min if self.min is not None else out.get("minimum", -LIMIT)
        out["maximum"] = self.max if self.max is not None else LIMIT
        return out


def _num(x: float) -> str:
    return f"{x:g}" if isinstance(x, float) else str(x)


class Text(Node):
    """A string, optionally one of ``choices`` or matching ``pattern`` (described by ``shape``)."""

    __slots__ = ("choices", "pattern", "shape", "nonempty", "max_len", "ignore_case")

    def __init__(self, choices: tuple[str, ...] = (),
                 pattern: str | None = None, shape: str = "", nonempty: bool = False,
                 max_len: int | None = None, ignore_case: bool = False):
        self.choices = choices
        self.pattern = pattern
        self.shape = shape  # what the pattern means, for messages and docs
        self.nonempty = nonempty
        self.max_len = max_len
        self.ignore_case = ignore_case

    def check(self, value, path, ctx):
        if not isinstance(value, str):
            raise SchemaError(path, value, f"must be a string, not {_kind(value)}")
        if self.choices and (value.upper() if self.ignore_case else value) not in self.choices:
            raise SchemaError(path, value, f"must be one of {', '.join(map(show, self.choices))}")
        if self.pattern and not re.fullmatch(self.pattern, value, re.I if self.ignore_case else 0):
            raise SchemaError(path, value, f"must be {self.shape or 'of the form ' + self.pattern}")
        if self.nonempty and not value or self.max_len is not None and len(value) > self.max_len:
            raise SchemaError(path, value, f"must have 1 to {self.max_len} characters" if self.max_len
                              else "must not be empty")

    def type_text(self):
        return "a string"

    def rule_text(self):
        if self.choices:
            return "one of " + ", ".join(f"`{show(c)}`" for c in self.choices)
        parts = [self.shape] if self.shape else []
        if self.max_len:
            parts.append(f"1 to {self.max_len} characters")
        elif self.nonempty:
            parts.append("not empty")
        return ", ".join(parts)

    def json(self):
        out: dict = {"type": "string"}
        if self.choices and not self.ignore_case:
            out["enum"] = list(self.choices)
        elif self.choices:  # JSON Schema patterns have no case-insensitive flag: [Gg]54
            out["pattern"] = "^(?:" + "|".join("".join(f"[{c.upper()}{c.lower()}]" if c.isalpha() else re.escape(c)
                                                       for c in choice) for choice in self.choices) + ")$"
        if self.pattern:
            out["pattern"] = f"^(?:{_either_case(self.pattern) if self.ignore_case else self.pattern})$"
        if self.nonempty:
            out["minLength"] = 1
        if self.max_len:
            out["maxLength"] = self.max_len
        return out


def _either_case(pattern: str) -> str:
    """``pattern`` matching letters in either case (JSON Schema patterns have no flag for it): R? -> [Rr]?,
    [SP] -> [SPsp]. Enough for the patterns declared here (no letter ranges)."""
    out, in_class, escaped = [], False, False
    for c in pattern:
        if escaped or not c.isalpha():
            out.append(c)
            escaped = c == "\\" and not escaped
            in_class = (in_class or c == "[") and c != "]" if not escaped else in_class
            continue
        out.append(c.upper() + c.lower() if in_class else f"[{c.upper()}{c.lower()}]")
    return "".join(out)


class Flag(Node):
    """``true`` or ``false`` (not 1, not "yes")."""

    __slots__ = ()

    def check(self, value, path, ctx):
        if not isinstance(value, bool):
            raise SchemaError(path, value, "must be true or false")

    def type_text(self):
        return "a boolean"

    def json(self):
        return {"type": "boolean"}


class Check(FrozenRecord):
    """A rule across the keys of a table (min <= max, no repeated numbers ...); ``doc`` goes into the docs."""

    __slots__ = ("doc", "fn")

    def __init__(self, doc: str, fn: Callable[[Any, str, Ctx], None]):
        self.doc = doc
        self.fn = fn


def unique(key: str, what: str, key_of: Callable[[Any, int], Any] | None = None) -> Check:
    """No two entries of an array share ``key`` (strings compared in upper case). ``key_of(entry, i)``
    gives it for an entry that leaves it out; an entry that is not a table is its own key."""
    def fn(items: list, path: str, ctx: Ctx) -> None:
        seen: dict = {}
        for i, item in enumerate(items):
            given = isinstance(item, dict) and key in item
            v = item[key] if given else key_of(item, i) if key_of else None if isinstance(item, dict) else item
            if v is None:
                continue
            k = v.upper() if isinstance(v, str) else v
            if k in seen:
                raise SchemaError(join(join(path, i), key) if given else join(path, i), v,
                                  f"repeats {join(path, seen[k])}: {what} must differ")
            seen[k] = i
    return Check(f"no two with the same {what}", fn)


class ListOf(Node):
    """An array of ``item`` s; ``per_axis``: exactly one per machine axis."""

    __slots__ = ("item", "min_len", "max_len", "per_axis", "checks")

    def __init__(self, item: Node,
                 min_len: int = 0, max_len: int | None = None, per_axis: bool = False,
                 checks: tuple[Check, ...] = ()):
        self.item = item
        self.min_len = min_len
        self.max_len = max_len
        self.per_axis = per_axis
        self.checks = checks

    def check(self, value, path, ctx):
        if not isinstance(value, list):
            raise SchemaError(path, value, f"must be {self.type_text()}, not {_kind(value)}")
        if self.per_axis and len(value) != len(ctx.axis_names):
            raise SchemaError(path, value, f"must give {len(ctx.axis_names)} value{'s' if len(ctx.axis_names) != 1 else ''}, one per axis "
                                           f"({', '.join(ctx.axis_names)})")
        if len(value) < self.min_len or self.max_len is not None and len(value) > self.max_len:
            raise SchemaError(path, value, f"must have {self._count()}")
        for i, v in enumerate(value):
            self.item.check(v, join(path, i), ctx)
        for c in self.checks:
            c.fn(value, path, ctx)

    def _count(self) -> str:
        if self.max_len is None:
            return "at least one entry" if self.min_len == 1 else f"at least {self.min_len} entries"
        if self.min_len == self.max_len:
            return f"{self.min_len} entries"
        return f"{self.min_len} to {self.max_len} entries" if self.min_len else f"at most {self.max_len} entries"

    def type_text(self):
        return f"an array of {_plural(self.item.type_text())}"

    def rule_text(self):
        parts = ["one per axis"] if self.per_axis else []
        if self.min_len or self.max_len is not None:
            parts.append(self._count())
        inner = self.item.rule_text()
        if inner:
            parts.append(f"each {inner}")
        parts += [c.doc for c in self.checks]
        return "; ".join(parts)

    def json(self):
        out: dict = {"type": "array", "items": self.item.json()}
        if self.min_len:
            out["minItems"] = self.min_len
        if self.max_len is not None:
            out["maxItems"] = self.max_len
        return out


def _plural(text: str) -> str:
    for a, b in (("an integer", "integers"), ("a number", "numbers"), ("a string", "strings"),
                 ("a boolean", "booleans"), ("a table", "tables"), ("an array", "arrays")):
        if text.startswith(a):
            return b + text[len(a):]
    return text


class Field(FrozenRecord):
    """One key of a table: its type, unit, default and meaning."""

    __slots__ = ("name", "type", "doc", "default", "unit", "required")

    def __init__(self, name: str,
                 type: Node, doc: str, default: Any = NO_DEFAULT, unit: str = "", required: bool = False):
        self.name = name
        self.type = type
        self.doc = doc
        self.default = default  # shown in the docs (what the control does when the key is left out)
        self.unit = unit
        self.required = required


class Table(Node):
    """A TOML table with the keys ``fields``; other keys only if ``other`` types them (their names must
    match ``keys``). Any other key is an error naming it."""

    __slots__ = ("fields", "other", "keys", "keys_doc", "checks", "closed_why")

    def __init__(self, fields: tuple[Field, ...] = (),
                 other: Node | None = None, keys: Text | None = None, keys_doc: str = "",
                 checks: tuple[Check, ...] = (), closed_why: str = ""):
        self.fields = fields
        self.other = other
        self.keys = keys  # the names ``other`` keys may have
        self.keys_doc = keys_doc  # what an ``other`` key stands for, in the docs
        self.checks = checks
        self.closed_why = closed_why  # why an empty table takes no keys at all (for the message)

    def check(self, value, path, ctx):
        if not isinstance(value, dict):
            raise SchemaError(path, value, f"must be a table, not {_kind(value)}")
        by_name = {f.name: f for f in self.fields}
        for key, v in value.items():
            sub = join(path, key)
            f = by_name.get(key)
            if f is not None:
                f.type.check(v, sub, ctx)
                continue
            if self.other is None:
                raise SchemaError(sub, v, self._unknown())
            if self.keys is not None:
                try:
                    self.keys.check(key, sub, ctx)
                except SchemaError as e:
                    raise SchemaError(sub, v, f"unknown key: a {self.keys_doc or 'key'} here {e.why}") from None
            self.other.check(v, sub, ctx)
        for f in self.fields:
            if f.required and f.name not in value:
                raise SchemaError(join(path, f.name), MISSING, "is missing (it is required)")
        for c in self.checks:
            c.fn(value, path, ctx)

    def _unknown(self) -> str:
        if not self.fields:
            return f"unknown key ({self.closed_why or 'this table takes no keys'})"
        why = f"; {self.closed_why}" if self.closed_why else ""
        return f"unknown key (known: {', '.join(f.name for f in self.fields)}{why})"

    def is_map(self) -> bool:
        """Only free keys, no declared ones: documented in one line as key -> value."""
        return not self.fields and self.other is not None

    def type_text(self):
        if self.is_map():
            return f"a table of {_plural(self.other.type_text())}"
        return "a table"

    def rule_text(self):
        parts = []
        if self.is_map():
            keys = self.keys.rule_text() if self.keys is not None else ""
            parts.append(f"keys: {self.keys_doc or 'any'}{' (' + keys + ')' if keys else ''}")
            if self.other.rule_text():
                parts.append(f"values: {self.other.rule_text()}")
        return "; ".join(parts + [c.doc for c in self.checks])

    def json(self):
        out: dict = {"type": "object", "properties": {f.name: _with_doc(f) for f in self.fields}}
        req = [f.name for f in self.fields if f.required]
        if req:
            out["required"] = req
        if self.other is None:
            out["additionalProperties"] = False
        else:
            out["additionalProperties"] = self.other.json()
            if self.keys is not None:
                out["propertyNames"] = self.keys.json()
        return out


def _with_doc(f: Field) -> dict:
    out = dict(f.type.json())
    text = f.doc + (f" ({f.unit})" if f.unit else "")
    rule = f.type.rule_text()
    out["description"] = text + (f"; {rule}" if rule and rule not in text else "")
    if f.default is not NO_DEFAULT and not isinstance(f.default, Said):
        out["default"] = f.default
    return out


class Either(Node):
    """One of several shapes (a program name or a table with program and modal ...), tried in order."""

    __slots__ = ("options", "what")

    def __init__(self, options: tuple[Node, ...], what: str):
        self.options = options
        self.what = what  # the shapes in words, for messages

    def check(self, value, path, ctx):
        fitting = [o for o in self.options if _fits(o, value)]
        if len(fitting) == 1:  # the value has the shape of one option: its error says most
            fitting[0].check(value, path, ctx)
            return
        last = None
        for opt in self.options:
            try:
                opt.check(value, path, ctx)
                return
            except SchemaError as e:
                if e.path != path:  # the value had the shape of this option; report the error inside it
                    raise
                last = e
        raise SchemaError(path, value, f"must be {self.what}" + (f" ({last.why})" if last and
                                                                  len(self.options) == 1 else ""))

    def type_text(self):
        return self.what

    def rule_text(self):
        return "; ".join(r for r in (o.rule_text() for o in self.options) if r)

    def json(self):
        return {"anyOf": [o.json() for o in self.options]}


def _fits(node: Node, value: Any) -> bool:
    """``value`` has the TOML type ``node`` takes (an array for an array, a table for a table ...)."""
    if isinstance(node, Either):
        return any(_fits(o, value) for o in node.options)
    kind = {Number: (int, float), Text: str, Flag: bool, ListOf: list, Table: dict, Tagged: dict}
    want = next((t for cls, t in kind.items() if isinstance(node, cls)), object)
    return isinstance(value, want) and (want is bool or not isinstance(value, bool))


class Tagged(Node):
    """A table whose ``tag`` key (e.g. a scenario event's ``kind``) chooses which other keys it has."""

    __slots__ = ("tag", "common", "cases")

    def __init__(self, tag: str, common: tuple[Field, ...], cases: dict[str, Table] | None = None):
        self.tag = tag
        self.common = common
        self.cases = {} if cases is None else cases

    def check(self, value, path, ctx):
        if not isinstance(value, dict):
            raise SchemaError(path, value, f"must be a table, not {_kind(value)}")
        if self.tag not in value:
            raise SchemaError(join(path, self.tag), MISSING, f"is missing (one of {', '.join(self.cases)})")
        kind = value[self.tag]
        if not isinstance(kind, str) or kind not in self.cases:
            raise SchemaError(join(path, self.tag), kind, f"must be one of {', '.join(map(show, self.cases))}")
        self.table(kind).check(value, path, ctx)

    def table(self, kind: str) -> Table:
        case = self.cases[kind]
        tag = Field(self.tag, Text(choices=tuple(self.cases)), f"what happens: {', '.join(self.cases)}",
                    required=True)
        return Table((*self.common, tag, *case.fields), case.other, case.keys, case.keys_doc, case.checks)

    def type_text(self):
        return "a table"

    def json(self):
        cases = []
        for kind in self.cases:
            schema = self.table(kind).json()
            schema["properties"][self.tag] = {"const": kind}
            cases.append(schema)
        return {"type": "object", "required": [self.tag], "oneOf": cases}


NO_AXES = Ctx()


def validate(node: Node, value: Any, ctx: Ctx = NO_AXES, path: str = "") -> None:
    """Raise :class:`SchemaError` at the first place ``value`` breaks ``node``."""
    node.check(value, path, ctx)
