"""One cache of built CasADi objects per thread, bounded (least recently used evicted).

A CasADi ``Function``/``nlpsol`` instance must never be called by two threads at once (it evaluates in one
shared memory slot). Every builder of such objects in the numerics (the chain solvers, the path systems,
the inverse-statics steps, the design NLPs) is wrapped by :func:`per_thread`: each thread builds and owns
its instances, keyed by the builder's arguments, so an instance built by one thread is only ever called by
that thread, and every public function of the library may be called from several threads at once.
"""

from __future__ import annotations

import functools
import threading
from collections import OrderedDict
from collections.abc import Callable
from typing import TypeVar

__all__ = ["CACHE_SIZE", "per_thread"]

#: Objects kept per thread and builder (least recently used evicted): a short chain's solver costs ~1-2 MB.
CACHE_SIZE = 16

T = TypeVar("T")


def per_thread(build: Callable[..., T] | None = None, *, maxsize: int = CACHE_SIZE,
               built: Callable[[T], None] | None = None, stale: Callable[[T], bool] | None = None):
    """Decorator: ``build(*args)`` cached per thread and positional arguments (hashable), at most ``maxsize``
    entries per thread (LRU). ``built(value)``, when given, runs after a new value is cached (e.g. a deadline
    check after a build that cannot be cut); ``stale(value)``, when given, says a cached value must be built
    again (one running in the virtual machine whose compiled code is ready). The wrapped function has
    ``cache_clear()`` (the calling thread's entries)."""

    def wrap(build: Callable[..., T]) -> Callable[..., T]:
        local = threading.local()

        @functools.wraps(build)
        def cached(*args) -> T:
            cache = getattr(local, "cache", None)
            if cache is None:
                cache = local.cache = OrderedDict()
            value = cache.get(args)
            if value is not None and stale is not None and stale(value):
                value = None
            if value is None:
                value = cache[args] = build(*args)
                while len(cache) > maxsize:
                    cache.popitem(last=False)
                if built is not None:
                    built(value)
            else:
                cache.move_to_end(args)
            return value

        cached.cache_clear = lambda: getattr(local, "cache", OrderedDict()).clear()
        return cached

    return wrap if build is None else wrap(build)
