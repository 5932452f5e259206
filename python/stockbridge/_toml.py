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
