"""griffe extension (mkdocstrings-python ``extensions:``): Sphinx cross-reference roles as inline code.

The docstrings are numpydoc and use Sphinx roles (``:func:`~tensegrity_opt.trace_branch```, ``:mod:`x```),
which mkdocstrings does not interpret. Each becomes inline code of its target, shortened to its last part
where the role says ``~`` (as Sphinx shows it), before the docstring is parsed. Text only: no link, so a
role naming an object that the reference does not render cannot break the strict build.
"""

from __future__ import annotations

import re
from typing import Any

from griffe import Extension

ROLE = re.compile(r":(?:py:)?(?:func|class|mod|meth|data|attr|exc|obj|const):`(~?)([^`<]+?)(?:\s*<([^>]+)>)?`")


def plain(text: str) -> str:
    """``text`` with every Sphinx role replaced by inline code of its (shortened) target."""
    def repl(mt: re.Match) -> str:
        tilde, target, explicit = mt.group(1), mt.group(2).strip(), mt.group(3)
        if explicit:                                   # :func:`title <target>`: the title
            return f"`{target}`"
        return f"`{target.rsplit('.', 1)[-1] if tilde else target}`"
    return ROLE.sub(repl, text)


class SphinxRoles(Extension):
    """Rewrite the roles of every object's docstring as it is loaded."""

    def on_instance(self, *, obj: Any, **kwargs: Any) -> None:
        if obj.docstring is not None:
            obj.docstring.value = plain(obj.docstring.value)
