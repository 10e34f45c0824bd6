"""Where work runs: one executor interface, threads and killable processes, one IPC protocol.

* :mod:`.executor` - the interface (:class:`Executor`: ``await run(fn, *args, timeout=...)``) and its refusals
  (:class:`Saturated`, :class:`Unavailable`, :class:`SolveTimeout`);
* :mod:`.threads` - :class:`ThreadExecutor`: solver threads, a bounded queue, the interrupt of a call past its
  deadline;
* :mod:`.processes` - :class:`ProcessExecutor`: child processes answering calls in order, killed when they
  cannot stop; :mod:`.ipc` their protocol (frames over a socketpair), :mod:`.child` their entry point;
* :mod:`.slots` - :class:`StreamSlots`: one thread per control stream;
* :mod:`.runtime` - :class:`Executors`: the executors of one server.

Nothing here knows a request, a task or the library's answers: the callers hand functions over.
"""

from .executor import Executor, Saturated, SolveTimeout, Unavailable
from .processes import ProcessExecutor
from .runtime import Executors
from .slots import StreamSlots
from .threads import ThreadExecutor

__all__ = ["Executor", "Saturated", "SolveTimeout", "Unavailable", "ThreadExecutor", "ProcessExecutor",
           "StreamSlots", "Executors"]
