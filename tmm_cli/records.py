"""Result records: frozen dataclasses that cost less to define.

Every result of the core is a frozen dataclass. Python 3.11 compiles six small functions for each
(``__init__``, the ``__setattr__`` and ``__delattr__`` that freeze it, ``__repr__``, ``__eq__``,
``__hash__``): about 0.7 ms a class, 33 ms for the 46 classes a `tmm project` run defines, a sixth
of a whole ``--json`` run. :func:`record` lets :mod:`dataclasses` compile the three that must know
the fields and gives every record the same three shared functions for the rest, which behave as the
generated ones do: equal when of the same class with equal fields, the hash of the fields, and
``Name(field=value, ...)``.

>>> @record
... class Point:
...     x: float
...     y: float = 0.0
>>> p = Point(1.0)
>>> p, p == Point(1.0), p == Point(2.0), hash(p) == hash(Point(1.0))
(Point(x=1.0, y=0.0), True, False, True)
>>> p.x = 3.0
Traceback (most recent call last):
dataclasses.FrozenInstanceError: cannot assign to field 'x'
"""

from __future__ import annotations

import dataclasses
import reprlib


def _compared(obj) -> tuple:
    return tuple(getattr(obj, name) for name in obj.__record_compare__)


def _eq(self, other):
    if other.__class__ is self.__class__:
        return _compared(self) == _compared(other)
    return NotImplemented


def _hash(self) -> int:
    return hash(_compared(self))


@reprlib.recursive_repr()
def _repr(self) -> str:
    fields = ", ".join(f"{name}={getattr(self, name)!r}" for name in self.__record_repr__)
    return f"{self.__class__.__qualname__}({fields})"


def record(cls=None, /, *, eq: bool = True):
    """``dataclass(frozen=True, eq=eq)``, cheaper to define (see the module's text).

    ``eq=False`` keeps identity equality and hashing (a record holding numpy arrays, whose ``==``
    has no single truth value).
    """

    def wrap(cls):
        cls = dataclasses.dataclass(frozen=True, eq=False, repr=False)(cls)
        fields = dataclasses.fields(cls)
        cls.__record_repr__ = tuple(f.name for f in fields if f.repr)
        cls.__repr__ = _repr
        if eq:
            cls.__record_compare__ = tuple(f.name for f in fields if f.compare)
            cls.__eq__ = _eq
            cls.__hash__ = _hash
        return cls

    return wrap if cls is None else wrap(cls)
