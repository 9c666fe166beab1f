"""Arguments of the wrong Python type, named in one line.

pybind11 refuses an argument it cannot convert with a TypeError of four lines
or more (every signature and the whole call). Every function, constructor,
method and property setter of the extension is wrapped once, when the package
is imported (``name_wrong_types``): a call pybind11 refuses is bound to the
signature in its docstring and the first argument whose value cannot be of its
parameter's type is named, as ``cueball.InvalidArgumentType`` (an
``InvalidArgument`` whose ``field`` is the argument's name, and a
``TypeError``): ``speed = 'fast' is a str; allowed: float``. A str holding a
lone UTF-16 surrogate (no UTF-8 for it) is named so too. A call of the wrong
shape (an unknown keyword, too many positional arguments, a required one
missing) stays a TypeError, one line as Python's own. Calls pybind11 accepts
are passed through unchanged (the wrapper costs some 0.25 us a call). The
extension's own conversions inside its functions name their argument the same
way (python/src/convert.cpp: cast_argument, utf8_argument).
"""

from __future__ import annotations

import functools
import os
import re
import types
from typing import Any, Callable, Dict, List, Optional, Tuple

_MAX_ECHOED = 60  # characters of an echoed value, as the library's messages (kMaxEchoedChars)
_MODULE_PREFIX = "cueball._cueball."


class _Parameter:
    __slots__ = ("name", "annotation", "has_default", "keyword_only")

    def __init__(self, name: str, annotation: str, has_default: bool, keyword_only: bool) -> None:
        self.name = name
        self.annotation = annotation
        self.has_default = has_default
        self.keyword_only = keyword_only


def _split_top_level(text: str) -> List[str]:
    """Splits at commas outside brackets (quotes are not followed: a default's
    description may hold an apostrophe, "the model's own")."""
    parts: List[str] = []
    depth = 0
    start = 0
    for i, c in enumerate(text):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return [p.strip() for p in parts if p.strip()]


def _parameter_pieces(text: str) -> List[str]:
    """The parameters of a signature's text: pieces that do not start a
    parameter ('name: ...', '*', '*args') belong to the previous one's default."""
    pieces: List[str] = []
    for piece in _split_top_level(text):
        if pieces and not re.match(r"^(\*{1,2}\w*|\w+: )", piece):
            pieces[-1] += ", " + piece
        else:
            pieces.append(piece)
    return pieces


def _signatures(doc: Optional[str], name: str) -> List[List[_Parameter]]:
    """The parameter lists of the signatures pybind11 wrote at the top of `doc`."""
    lines = (doc or "").splitlines()
    if not lines:
        return []
    if len(lines) > 1 and lines[1].startswith("Overloaded function."):
        heads = [line.split(". ", 1)[1] for line in lines if re.match(r"^\d+\. ", line)]
    else:
        heads = [lines[0]]
    out: List[List[_Parameter]] = []
    for head in heads:
        if not head.startswith(name + "("):
            continue
        inside = head[len(name) + 1 :]
        depth, end = 1, -1
        for i, c in enumerate(inside):
            if c in "([{":
                depth += 1
            elif c in ")]}":
                depth -= 1
                if depth == 0:
                    end = i
                    break
        if end < 0:
            continue
        parameters: List[_Parameter] = []
        keyword_only = False
        for piece in _parameter_pieces(inside[:end]):
            if piece == "*":
                keyword_only = True
                continue
            if piece.startswith("*"):  # *args, **kwargs: anything goes
                return []
            declared, _, default = piece.partition(" = ")
            pname, _, annotation = declared.partition(": ")
            parameters.append(_Parameter(pname.strip(), annotation.strip(), bool(default), keyword_only))
        out.append(parameters)
    return out


def _bind(parameters: List[_Parameter], args: Tuple[Any, ...], kwargs: Dict[str, Any],
          shown: str) -> Tuple[List[Tuple[_Parameter, Any]], Optional[str]]:
    """The arguments bound to their parameters, or the call's shape error (as Python words it)."""
    positional = [p for p in parameters if not p.keyword_only]
    if len(args) > len(positional):
        return [], f"{shown}() takes at most {len(positional)} positional arguments ({len(args)} given)"
    bound = list(zip(positional, args))
    named = {p.name: p for p in parameters}
    taken = {p.name for p, _ in bound}
    for key, value in kwargs.items():
        if key not in named:
            return [], f"{shown}() got an unexpected keyword argument {key!r}"
        if key in taken:
            return [], f"{shown}() got multiple values for argument {key!r}"
        bound.append((named[key], value))
        taken.add(key)
    for p in parameters:
        if p.name not in taken and not p.has_default:
            return [], f"{shown}() missing required argument {p.name!r}"
    return bound, None


def _is_sequence(value: Any) -> bool:
    return (not isinstance(value, (str, bytes, bytearray, dict)) and hasattr(type(value), "__getitem__")
            and hasattr(type(value), "__len__"))


def _surrogate(text: str) -> Optional[str]:
    for i, c in enumerate(text):
        if "\ud800" <= c <= "\udfff":
            return f"U+{ord(c):04X} at index {i}"
    return None


def _generic(annotation: str) -> Tuple[str, List[str]]:
    """'Optional[List[int]]' -> ('Optional', ['List[int]']); 'float' -> ('float', [])."""
    match = re.match(r"^([\w.]+)\[(.*)\]$", annotation)
    if not match:
        return annotation, []
    return match.group(1), _split_top_level(match.group(2))


def _refusal(annotation: str, value: Any, module: types.ModuleType) -> Optional[str]:
    """Why pybind11 cannot convert `value` to `annotation` (with conversions
    allowed), or None when it can or when the annotation is not understood."""
    kind, inner = _generic(annotation)
    if kind == "float":
        ok = hasattr(type(value), "__float__") or hasattr(type(value), "__index__")
        return None if ok else "type"
    if kind == "int":
        if isinstance(value, float) or not (hasattr(type(value), "__index__") or hasattr(type(value), "__int__")):
            return "type"
        return None
    if kind == "bool":
        ok = value is None or isinstance(value, bool) or hasattr(type(value), "__bool__")
        return None if ok else "type"
    if kind == "str":
        if isinstance(value, str):
            where = _surrogate(value)
            return None if where is None else "surrogate " + where
        return None if isinstance(value, (bytes, bytearray)) else "type"
    if kind == "Optional" and len(inner) == 1:
        return None if value is None else _refusal(inner[0], value, module)
    if kind == "Union":
        refusals = [_refusal(a, value, module) for a in inner]
        return None if any(r is None for r in refusals) else "type"
    if kind in ("List", "Set") and len(inner) == 1:
        if kind == "Set" and isinstance(value, (set, frozenset)):
            items = list(value)
        elif _is_sequence(value):
            items = list(value)
        else:
            return "type"
        element, sized = inner[0], re.match(r"^(.*)\[(\d+)\]$", inner[0])
        if sized and not sized.group(1).endswith("]"):  # std::array: List[float[2]]
            element = sized.group(1)
            if len(items) != int(sized.group(2)):
                return f"length {len(items)}, not {sized.group(2)}"
        for item in items:
            if _refusal(element, item, module) is not None:
                return "element"
        return None
    if kind == "Tuple":
        if not _is_sequence(value) or len(value) != len(inner):
            return "type"
        return None if all(_refusal(a, v, module) is None for a, v in zip(inner, value)) else "element"
    if kind == "Dict" and len(inner) == 2:
        if not isinstance(value, dict):
            return "type"
        ok = all(_refusal(inner[0], k, module) is None and _refusal(inner[1], v, module) is None
                 for k, v in value.items())
        return None if ok else "element"
    if kind == "Callable":
        return None if callable(value) else "type"
    if kind == "os.PathLike":
        return None if isinstance(value, os.PathLike) else "type"
    if kind.startswith(_MODULE_PREFIX) and not inner:
        cls = getattr(module, kind[len(_MODULE_PREFIX):], None)
        if isinstance(cls, type):
            return None if isinstance(value, cls) else "type"
    return None  # object, numpy arrays and what this reading does not know


def _readable(annotation: str) -> str:
    kind, inner = _generic(annotation)
    if kind == "Optional" and len(inner) == 1:
        return _readable(inner[0]) + " or None"
    return annotation.replace(_MODULE_PREFIX, "")


def _echo(value: Any) -> str:
    text = repr(value).replace("\n", "\\n")
    return text if len(text) <= _MAX_ECHOED else text[:_MAX_ECHOED] + "\u2026"


def _message(field: str, annotation: str, value: Any, refusal: str) -> str:
    if refusal.startswith("surrogate "):
        return (f"{field} has a lone UTF-16 surrogate ({refusal[len('surrogate '):]}), which no UTF-8 text can "
                f"hold; allowed: valid Unicode text")
    detail = "" if refusal in ("type", "element") else f" of {refusal}"
    kind = type(value).__name__
    article = "an" if kind[:1] in "aeiou" else "a"
    return f"{field} = {_echo(value)} is {article} {kind}{detail}; allowed: {_readable(annotation)}"


def _invalid(module: types.ModuleType, field: str, message: str) -> BaseException:
    error: BaseException = module.InvalidArgumentType(message)
    setattr(error, "field", field)
    return error


def _diagnosis(module: types.ModuleType, func: Any, name: str, shown: str, args: Tuple[Any, ...],
               kwargs: Dict[str, Any], field: Optional[str]) -> Optional[BaseException]:
    """The one-line error for a call pybind11 refused, or None (keep pybind11's)."""
    shape: Optional[str] = None
    for parameters in _signatures(getattr(func, "__doc__", None), name):
        bound, shape_error = _bind(parameters, args, kwargs, shown)
        if shape_error is not None:
            shape = shape or shape_error
            continue
        # Type mismatches first; then an int beyond 32 bits (pybind11's C int).
        for parameter, value in bound:
            refusal = _refusal(parameter.annotation, value, module)
            if refusal is not None and parameter.name != "self":
                return _invalid(module, field or parameter.name,
                                _message(field or parameter.name, parameter.annotation, value, refusal))
        for parameter, value in bound:
            if _generic(parameter.annotation)[0] == "int" and isinstance(value, int) and not -2**31 <= value < 2**31:
                f = field or parameter.name
                return _invalid(module, f, f"{f} = {_echo(value)} is beyond the range of an integer argument")
    if shape is not None:
        return TypeError(shape)
    return None


def _wrapped(module: types.ModuleType, func: Any, name: str, shown: str, qualname: str,
             field: Optional[str] = None) -> Callable[..., Any]:
    refused = name + "(): incompatible "

    @functools.wraps(func)
    def call(*args: Any, **kwargs: Any) -> Any:  # noqa: ANN401
        try:
            return func(*args, **kwargs)
        except TypeError as error:
            if not str(error).startswith(refused):
                raise
            better = _diagnosis(module, func, name, shown, args, kwargs, field)
            if better is None:
                raise
            raise better from None

    call.__qualname__ = qualname  # a function pickles by reference, under this name
    return call


def name_wrong_types(module: types.ModuleType) -> None:
    """Wraps the extension's functions, constructors, methods and property
    setters in place (see the module's docstring). Idempotent."""
    if getattr(module, "__wrong_types_named__", False):
        return
    for name, obj in list(vars(module).items()):
        if isinstance(obj, types.BuiltinFunctionType) and not name.startswith("__"):
            setattr(module, name, _wrapped(module, obj, name, name, name))
        elif isinstance(obj, type) and not issubclass(obj, BaseException) and obj.__module__ == module.__name__:
            for member_name, member in list(vars(obj).items()):
                if member_name.startswith("_") and member_name != "__init__":
                    continue
                qualname = f"{obj.__name__}.{member_name}"
                shown = obj.__name__ if member_name == "__init__" else qualname
                if type(member).__name__ == "instancemethod":
                    setattr(obj, member_name, _wrapped(module, member.__func__, member_name, shown, qualname))
                elif isinstance(member, staticmethod):
                    wrapped = _wrapped(module, member.__func__, member_name, shown, qualname)
                    setattr(obj, member_name, staticmethod(wrapped))
                elif type(member) is property and member.fset is not None:
                    setter = _wrapped(module, member.fset, "", shown, qualname, field=member_name)
                    setattr(obj, member_name, property(member.fget, setter, member.fdel, member.__doc__))
    setattr(module, "__wrong_types_named__", True)
