"""Python values as TOML text, for make_cable and make_damper: the library reads
that text with the same reader, checks and messages as a user's file, so a value
built in Python is validated exactly as one written in a file."""

import json
import math
import numbers


def value(v):
    """A TOML value: numbers (numpy's too), strings, booleans, lists and (inline) dicts."""
    if isinstance(v, bool) or type(v).__name__ == "bool_":
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        v = float(v)
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)  # a TOML basic string (no surrogate escapes)
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{key(k)} = {value(x)}" for k, x in v.items()) + " }"
    if hasattr(v, "toml"):  # a Cable
        raise TypeError("a Cable goes in as a table, not as a value")
    try:
        items = list(v)
    except TypeError:
        raise TypeError(f"{v!r}: expected a number, a string, a list or a dict") from None
    return "[ " + ", ".join(value(x) for x in items) + " ]"


def key(k):
    k = str(k)
    return k if k.replace("_", "").replace("-", "").isalnum() and k.isascii() else json.dumps(k)


def table(name, entries):
    """`[name]` and its keys; a Cable's own keys where `entries` is a Cable."""
    if hasattr(entries, "toml"):
        return f"[{name}]\n" + entries.toml()
    return f"[{name}]\n" + "".join(f"{key(k)} = {value(v)}\n" for k, v in entries.items())


def document(tables, prefix=""):
    """A whole document from nested dicts (tomllib's form): each dict a [table], each
    list of dicts an [[array of tables]], the rest `key = value`."""
    def is_table(v):
        return isinstance(v, dict)

    def is_table_array(v):
        return isinstance(v, list) and v and all(isinstance(x, dict) for x in v)

    lines = [f"{key(k)} = {value(v)}" for k, v in tables.items() if not is_table(v) and not is_table_array(v)]
    text = "".join(line + "\n" for line in lines)
    for k, v in tables.items():
        path = f"{prefix}.{key(k)}" if prefix else key(k)
        if is_table(v):
            text += f"\n[{path}]\n" + document(v, path)
        elif is_table_array(v):
            for entry in v:
                text += f"\n[[{path}]]\n" + document(entry, path)
    return text
