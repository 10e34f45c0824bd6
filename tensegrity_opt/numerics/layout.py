"""Named blocks of a flat vector: how an NLP's variables, rows and parameters (or a kernel's outputs) are laid out.

The idea of do-mpc's named CasADi structs, for numpy: a :class:`Layout` knows each block's name, size and
place, so a caller packs and unpacks by name and never computes an offset::

    x = nlp.x.pack(phi=np.cumsum(q), L10=l1, L20=l2, mu=0.1, L=factor, Y=y, s=0.0)
    nlp.x.unpack(res.x)["mu"]

Blocks are vectors (a size) or scalars (size ``()``: unpacked as a number, or one per row).
"""

from __future__ import annotations

import numpy as np

__all__ = ["Layout"]


class Layout:
    """Named blocks of a flat vector, in order.

    Parameters
    ----------
    **blocks : int or ()
        Each block's size, in the order of the vector; ``()`` for a scalar.
    """

    def __init__(self, **blocks: int | tuple[()]) -> None:
        self.places: dict[str, slice | int] = {}
        at = 0
        for name, size in blocks.items():
            if size == ():
                self.places[name] = at
                at += 1
            else:
                self.places[name] = slice(at, at + int(size))
                at += int(size)
        self.size = at

    def __len__(self) -> int:
        return self.size

    def __getitem__(self, name: str) -> slice | int:
        """Where block ``name`` sits: a slice, or an index for a scalar."""
        return self.places[name]

    def __repr__(self) -> str:
        return f"Layout({', '.join(f'{k}={v}' for k, v in self.places.items())}; size {self.size})"

    def unpack(self, x) -> dict[str, np.ndarray | float]:
        """The blocks of ``x`` by name: views along its last axis (rows of a matrix unpack block by block)."""
        x = np.asarray(x)
        if x.shape[-1] != self.size:
            raise ValueError(f"expected {self.size} entries along the last axis, got {x.shape[-1]}")
        return {name: x[..., place] for name, place in self.places.items()}

    def pack(self, **values) -> np.ndarray:
        """The flat vector from every block by name (a number fills its block)."""
        if values.keys() != self.places.keys():
            missing = self.places.keys() - values.keys()
            unknown = values.keys() - self.places.keys()
            raise ValueError(f"pack needs exactly the blocks {list(self.places)}: missing {sorted(missing)}, "
                             f"unknown {sorted(unknown)}")
        out = np.empty(self.size)
        for name, place in self.places.items():
            out[place] = values[name]
        return out
