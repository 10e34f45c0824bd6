"""Named blocks of a flat vector: how an NLP's variables, rows and parameters (or a kernel's outputs) are laid out.

The idea of do-mpc's named CasADi structs, for numpy: a :class:`Layout` knows each block's name, size and
place, so a caller packs and unpacks by name and never computes an offset::

    x = nlp.x.pack(phi=np.cumsum(q), L10=l1, L20=l2, mu=0.1, L=factor, Y=y, s=0.0)
    nlp.x.unpack(res.x)["mu"]

Blocks are vectors (a size) or scalars (size ``()``: unpacked as a number, or one per row).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

__all__ = ["Layout", "chain_parameters", "equilibrium_unknowns", "rest_lengths"]


class Layout:
    """Named blocks of a flat vector, in order.

    Parameters
    ----------
    **blocks : int or ()
        Each block's size, in the order of the vector; ``()`` for a scalar.
    """

    def __init__(self, **blocks: int | tuple[()]) -> None:
        self.places: dict[str, slice | int] = {}
        self._ends: dict[str, tuple[int, int]] = {}
        at = 0
        for name, size in blocks.items():
            width = 1 if size == () else int(size)
            self.places[name] = at if size == () else slice(at, at + width)
            self._ends[name] = (at, at + width)
            at += width
        self.size = at
        self._names = self.places.keys()
        self._items = tuple(self.places.items())        # packed and read on hot paths: no dict view per call

    def __len__(self) -> int:
        return self.size

    def __getitem__(self, name: str) -> slice | int:
        """Where block ``name`` sits: a slice, or an index for a scalar."""
        return self.places[name]

    def span(self, first: str, last: str) -> slice:
        """The blocks from ``first`` to ``last`` (both included, in the vector's order) as one slice: e.g. the
        columns of a Jacobian in the unknowns ``q`` through ``F``."""
        start, stop = self._ends[first][0], self._ends[last][1]
        if stop <= start:
            raise ValueError(f"block {last!r} comes before {first!r}")
        return slice(start, stop)

    def __repr__(self) -> str:
        return f"Layout({', '.join(f'{k}={v}' for k, v in self.places.items())}; size {self.size})"

    def unpack(self, x) -> dict[str, np.ndarray | float]:
        """The blocks of ``x`` by name: views along its last axis (rows of a matrix unpack block by block)."""
        x = np.asarray(x)
        if x.shape[-1] != self.size:
            raise ValueError(f"expected {self.size} entries along the last axis, got {x.shape[-1]}")
        return {name: x[..., place] for name, place in self._items}

    def pack(self, **values) -> np.ndarray:
        """The flat vector from every block by name (a number fills its block)."""
        if values.keys() != self._names:
            self._refuse(values)
        out = np.empty(self.size)
        for name, place in self._items:
            out[place] = values[name]
        return out

    def stack(self, rows: int, **values) -> np.ndarray:
        """``rows`` flat vectors as the rows of a matrix, from every block's rows by name (``rows`` values of a
        scalar block, ``rows x size`` of a vector block; a number fills its block in every row)."""
        if values.keys() != self._names:
            self._refuse(values)
        out = np.empty((rows, self.size))
        for name, place in self._items:
            out[:, place] = values[name]
        return out

    def _refuse(self, values: dict) -> None:
        missing = self._names - values.keys()
        unknown = values.keys() - self._names
        raise ValueError(f"pack needs exactly the blocks {list(self.places)}: missing {sorted(missing)}, "
                         f"unknown {sorted(unknown)}")


@lru_cache(maxsize=None)
def chain_parameters(n: int) -> Layout:
    """The solvers' parameters of a chain of ``n`` segments (:attr:`~tensegrity_opt.Manipulator.params`, and a
    direction in them): ``a``, ``b``, ``k1``, ``k2``, ``L10``, ``L20``, one entry per segment each."""
    return Layout(a=n, b=n, k1=n, k2=n, L10=n, L20=n)


@lru_cache(maxsize=None)
def equilibrium_unknowns(n: int) -> Layout:
    """The unknowns ``z`` of a chain's equilibrium (KKT) system: the absolute angles ``phi`` (n) and the tip force
    ``F`` (2); also the rows of its Jacobian's solves (:meth:`.ChainSolver.kkt_parameter_jacobian`)."""
    return Layout(phi=n, F=2)


@lru_cache(maxsize=None)
def rest_lengths(n: int) -> Layout:
    """The rest lengths of a chain's ``2 n`` springs as the design problems take them (the nominal ``L0nom``, the
    bounds of a preload problem): ``L10`` of every segment, then every ``L20``."""
    return Layout(L10=n, L20=n)
