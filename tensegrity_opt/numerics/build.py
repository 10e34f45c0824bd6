"""Generated C for CasADi Functions: compiled once per machine, loaded once per process, CasADi's VM otherwise.

Every compiled part of the numerics (the Newton kernels of :mod:`.kernels`, the path system of
:mod:`.path_system`, the inverse-statics step of :mod:`.inverse_statics`) comes through :func:`load`:

* the Functions are generated to C (``casadi.CodeGenerator``) and compiled with the system C compiler into
  ``TENSEGRITY_CACHE_DIR`` (default ``$XDG_CACHE_HOME/tensegrity_opt`` or ``~/.cache/tensegrity_opt``), one
  shared library per name, its file named by a hash of the generated code and the compiler command, so an
  upgrade never loads stale code; a library already there is loaded without compiling;
* the library's path is found once per process (under a lock per name: concurrent threads wait for the
  first one's build); every call returns new ``Function`` instances for the calling thread (a CasADi
  Function evaluates in its own memory and must not be called by two threads at once);
* without a compiler (``$CC`` or the first of ``cc``, ``gcc``, ``clang`` on the ``PATH``), with
  ``TENSEGRITY_COMPILE=0`` (or ``false``, ``no``, ``off``), or when compiling or loading fails, the same
  Functions run in CasADi's virtual machine: slower (about 4x for the Newton kernels), same results, never
  an error for the caller; one ``RuntimeWarning`` per process says so and why.

When a library is compiled
--------------------------
By default the first caller that needs a library not in the cache waits for the compiler (seconds; tens of
seconds on a loaded machine). In **background** mode (:func:`compile_in_background`, or
``TENSEGRITY_COMPILE=background``; the service's default) nobody waits: the caller gets the Functions in the
virtual machine at once (:attr:`Loaded.pending`) and one thread of the process (``tensegrity-compiler``, the
compiler at a lower priority) compiles the library; the callers' objects built on it check :func:`pending` and
load the compiled code once it is there (:func:`schedule` queues a library ahead of its first use). A library
whose file left the cache (a wiped cache directory) is compiled again, in the background in that mode. Processes
sharing a cache directory compile a library once (a lock file per library).
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import queue
import shutil
import subprocess
import tempfile
import threading
import warnings
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import casadi as ca

__all__ = ["COMPILED", "VIRTUAL_MACHINE", "Loaded", "load", "libraries", "cache_dir", "compiler", "compiler_name",
           "compile_in_background", "in_background", "pending", "schedule", "wait_built", "cached_library"]

#: How loaded Functions run.
COMPILED = "compiled"
VIRTUAL_MACHINE = "virtual machine"

_FLAGS = ["-O2", "-fPIC", "-shared"]
_lock = threading.Lock()                    # guards the two tables below
_name_locks: dict[str, threading.Lock] = {}
#: Per process and library name: the compiled library's path, or ``""`` when its Functions run in the VM.
_libraries: dict[str, str] = {}
#: The Function names of each library (its ``graphs()`` keys), per process.
_names: dict[str, tuple[str, ...]] = {}
_warned = False
#: Libraries queued or being compiled in the background (their callers run them in the VM meanwhile).
_pending: set[str] = set()
_queue: queue.Queue[tuple[str, str, Callable[[], dict[str, ca.Function]]]] = queue.Queue()
_builder: threading.Thread | None = None
_built = threading.Condition(_lock)
#: Set by :func:`compile_in_background` (``None``: ``TENSEGRITY_COMPILE`` decides).
_background: bool | None = None
#: The background builds run the compiler at this niceness (requests keep the CPU).
NICENESS = 10


def _warn(why: str) -> None:
    """One warning per process: compiled Functions run in CasADi's virtual machine, and why."""
    global _warned
    with _lock:
        if _warned:
            return
        _warned = True
    warnings.warn(f"tensegrity_opt: {why}; the compiled functions (Newton kernels, path systems, inverse statics) "
                  "run in CasADi's virtual machine instead (slower: about 4x for the Newton kernels; same results)",
                  RuntimeWarning, stacklevel=4)


def cache_dir() -> Path:
    """Directory of the compiled libraries (``TENSEGRITY_CACHE_DIR`` or the user's cache directory)."""
    env = os.environ.get("TENSEGRITY_CACHE_DIR")
    if env:
        return Path(env)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "tensegrity_opt"


def _switched_off() -> str | None:
    """The value of ``TENSEGRITY_COMPILE`` when it switches compilation off (``0``, ``false``, ``no``, ``off``)."""
    value = os.environ.get("TENSEGRITY_COMPILE", "1")
    return value if value.strip().lower() in ("0", "false", "no", "off") else None


def compile_in_background(on: bool = True) -> None:
    """The switch: ``True``, a library not compiled yet runs in the VM at once while this process compiles it in
    the background (see the module); ``False``, its first caller waits for the compiler (the default, unless
    ``TENSEGRITY_COMPILE=background``)."""
    global _background
    _background = bool(on)


def in_background() -> bool:
    """Whether libraries are compiled in the background (:func:`compile_in_background`)."""
    if _background is not None:
        return _background
    return os.environ.get("TENSEGRITY_COMPILE", "").strip().lower() == "background"


def pending(name: str) -> bool:
    """Whether the library ``name`` is queued or being compiled in the background."""
    return name in _pending


def wait_built(name: str, timeout: float | None = None) -> bool:
    """Wait until the library ``name`` is no longer :func:`pending`; ``False`` at ``timeout`` seconds."""
    with _built:
        return _built.wait_for(lambda: name not in _pending, timeout)


def schedule(name: str, what: str, graphs: Callable[[], dict[str, ca.Function]]) -> bool:
    """Queue the library ``name`` for the background compiler unless it is loaded or queued already (``True``
    when queued). A library already in the cache is only found there."""
    global _builder
    with _lock:
        if name in _pending or _libraries.get(name):
            return False
        _pending.add(name)
        _queue.put((name, what, graphs))
        if _builder is None or not _builder.is_alive():
            _builder = threading.Thread(target=_build_queued, name="tensegrity-compiler", daemon=True)
            _builder.start()
    return True


def _build_queued() -> None:
    while True:
        name, what, graphs = _queue.get()
        path = ""
        try:
            funcs = graphs()
            with _lock:
                _names[name] = tuple(funcs)
            path = _compile(name, what, funcs, background=True) or ""
        except Exception as exc:  # noqa: BLE001 - a failed build: the VM goes on, never fatal
            _warn(f"building {what} failed ({exc!r})")
        with _built:
            _libraries[name] = path
            _pending.discard(name)
            _built.notify_all()


def compiler() -> str | None:
    """The C compiler used (``$CC`` or ``cc``/``gcc``/``clang``), or ``None`` (then no compilation)."""
    if _switched_off() is not None:
        return None
    cc = os.environ.get("CC")
    if cc:
        path = shutil.which(cc)
        if path is None:
            _warn(f"the C compiler CC={cc!r} was not found")
        return path
    for name in ("cc", "gcc", "clang"):
        path = shutil.which(name)
        if path:
            return path
    return None


def compiler_name() -> str | None:
    """The C compiler used by name and version (``"cc 12.2.0"``), not where it is installed; ``None``: none."""
    path = compiler()
    return None if path is None else _name_and_version(path)


@lru_cache(maxsize=8)
def _name_and_version(path: str) -> str:
    name = Path(path).name
    for flag in ("-dumpfullversion", "-dumpversion"):          # gcc knows both, clang the second
        try:
            out = subprocess.run([path, flag], capture_output=True, text=True, timeout=10, check=False)
        except (OSError, subprocess.SubprocessError):
            break
        version = out.stdout.strip().splitlines()[0] if out.returncode == 0 and out.stdout.strip() else ""
        if version and len(version) <= 40 and "/" not in version:
            return f"{name} {version}"
    return name


def libraries() -> dict[str, str]:
    """The libraries loaded so far in this process: name -> path (``""``: running in the virtual machine)."""
    with _lock:
        return dict(_libraries)


@dataclass(frozen=True)
class Loaded:
    """The calling thread's instances of a library's Functions (by name) and how they run (:data:`COMPILED`
    or :data:`VIRTUAL_MACHINE`); ``pending``: in the VM while the library compiles in the background (load it
    again once :func:`pending` says it is no longer)."""

    functions: dict[str, ca.Function]
    mode: str
    pending: bool = False


def load(name: str, what: str, graphs: Callable[[], dict[str, ca.Function]]) -> Loaded:
    """The Functions ``graphs()`` (name -> Function, each named as its key) as compiled code, else in the VM.

    Parameters
    ----------
    name : str
        The library's name (one per set of Functions, e.g. ``tensegrity_kernels_n4``).
    what : str
        What the Functions are, for the warning (e.g. ``"the Newton kernels"``).
    graphs : callable
        Builds the Functions; called to generate the code (once per process) and for the virtual machine.
    """
    with _lock:
        name_lock = _name_locks.setdefault(name, threading.Lock())
    funcs = None
    with name_lock:
        path = _libraries.get(name)
        if path and not os.path.exists(path):           # the cache was wiped: compile it again
            with _lock:
                _libraries.pop(name, None)
            path = None
        if path is None:
            funcs = graphs()
            _names[name] = tuple(funcs)
            if in_background():
                if name in _pending:
                    return Loaded(funcs, VIRTUAL_MACHINE, pending=True)
                path = _compile(name, what, funcs, build=False)
                if path is None:                        # not in the cache: compiled meanwhile, the VM answers
                    schedule(name, what, graphs)
                    return Loaded(funcs, VIRTUAL_MACHINE, pending=True)
            else:
                path = _compile(name, what, funcs) or ""
            with _lock:
                _libraries[name] = path
    if path:
        try:
            return Loaded({key: ca.external(key, path) for key in _names[name]}, COMPILED)
        except RuntimeError as exc:                 # an unloadable library: never fatal
            _warn(f"loading {path} failed ({exc})")
            with _lock:
                _libraries[name] = ""
    return Loaded(funcs or graphs(), VIRTUAL_MACHINE)


def cached_library(name: str, graphs: Callable[[], dict[str, ca.Function]]) -> bool:
    """Whether the library ``name`` of the Functions ``graphs()`` is compiled in the cache (or already loaded
    compiled in this process); never compiles. Where it is, :func:`libraries` has its path."""
    with _lock:
        path = _libraries.get(name)
    if path and os.path.exists(path):
        return True
    cc = compiler()
    if cc is None:
        return False
    try:
        found = _compile_with(cc, name, graphs(), build=False)
    except (OSError, RuntimeError, subprocess.SubprocessError):
        return False
    if found:
        with _lock:
            _libraries[name] = found
        return True
    return False


def _compile(name: str, what: str, funcs: dict[str, ca.Function], *, build: bool = True,
             background: bool = False) -> str | None:
    """Generate C for ``funcs``, compile it into the cache (once per machine); the library's path, or
    ``None`` (with the warning) when anything on the way fails. ``build=False``: the path only when the library
    is in the cache already (``""`` when nothing can compile it), else ``None``; ``background``: the compiler runs
    at a lower priority."""
    cc = compiler()
    if cc is None:
        off = _switched_off()
        _warn(f"TENSEGRITY_COMPILE={off} switches compilation off" if off is not None else
              "no C compiler was found (CC, cc, gcc, clang; e.g. apt-get install gcc)")
        return None if build else ""
    try:
        return _compile_with(cc, name, funcs, build, background)
    except (OSError, RuntimeError, subprocess.SubprocessError) as exc:
        detail = (getattr(exc, "stderr", None) or b"").decode(errors="replace")[:300]
        _warn(f"compiling {what} with {cc} failed ({exc} {detail})")
        return None if build else ""


def _compile_with(cc: str, name: str, funcs: dict[str, ca.Function], build: bool = True,
                  background: bool = False) -> str | None:
    with tempfile.TemporaryDirectory(prefix="tensegrity-kernels-") as tmp:
        cg = ca.CodeGenerator(f"{name}.c", {"with_header": False})
        for f in funcs.values():
            cg.add(f)
        src_path = Path(cg.generate(tmp + os.sep))
        key = hashlib.sha256(src_path.read_bytes() + " ".join([cc, *_FLAGS, ca.__version__]).encode()).hexdigest()
        target = cache_dir() / f"{name}_{key[:16]}.so"
        if target.exists():
            return str(target)
        if not build:
            return None
        target.parent.mkdir(parents=True, exist_ok=True)
        with _file_lock(target.parent / f"{name}.lock"):   # another process may be compiling it
            if target.exists():
                return str(target)
            tmp_so = Path(tmp) / "out.so"
            nice = shutil.which("nice") if background else None
            prefix = [nice, "-n", str(NICENESS)] if nice else []
            subprocess.run([*prefix, cc, *_FLAGS, str(src_path), "-o", str(tmp_so), "-lm"], check=True,
                           capture_output=True, timeout=300)
            # atomic: readers never see half a file
            staged = target.with_name(f"{target.name}.{os.getpid()}.{threading.get_ident()}.tmp")
            shutil.copyfile(tmp_so, staged)
            os.replace(staged, target)
        return str(target)


@contextlib.contextmanager
def _file_lock(path: Path) -> Iterator[None]:
    """An exclusive lock on ``path`` between processes (none where ``fcntl`` is missing); the file is removed
    when the holder is done, so the cache holds libraries only."""
    try:
        import fcntl
    except ImportError:                             # pragma: no cover - not POSIX
        yield
        return
    with open(path, "a") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            # the library is in place (or failed): a later process finds it before it looks for the lock
            with contextlib.suppress(OSError):
                os.unlink(path)
            fcntl.flock(f, fcntl.LOCK_UN)
