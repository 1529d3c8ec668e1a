"""Harness of the reliability suite: runs smpl-export on bad input and checks
that it fails the way the project promises (README "Errors").

Each `*_cases.py` file beside this one builds its inputs in a scratch folder and
calls `expect_failure(...)` (or `expect_success(...)`) per case, then `finish()`.
A failure check asserts, for one process:
  - the exit code (1 usage, 2 load, 3 export, 4 write);
  - stderr ends with one line starting "Error" that names the expected file;
    every stderr line is printable (no raw bytes from a file reach the terminal);
  - no output file and no temporary file left in the output folders;
  - every input byte-identical afterwards (sha256);
  - peak memory (ru_maxrss of the child, from wait4: the kernel's own
    accounting) under a bound.
Run: /usr/bin/python3 tests/reliability/<x>_cases.py SMPL_EXPORT FIXTURE_DIR WORK_DIR
The last line printed is "reliability: N passed, N failed".
"""
import hashlib
import os
import pathlib
import subprocess
import sys
import time

_results = []  # (name, ok, detail)


def args():
    """(exe, fixture_dir, work_dir) from argv; work_dir is emptied. Exits with an
    error when exe is built with AddressSanitizer: its memory use is not the
    product's and it cannot run under an address-space limit (tests.cmake)."""
    if len(sys.argv) != 4:
        sys.exit(f"usage: {sys.argv[0]} SMPL_EXPORT FIXTURE_DIR WORK_DIR")
    exe, fixtures, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    if b"__asan_init" in pathlib.Path(exe).read_bytes():
        sys.exit(f"{exe}: built with AddressSanitizer; the reliability suite needs a product build "
                 "(configure with -DSMPL_RELIABILITY_EXE=<build>/cli/smpl-export; scripts/test.sh does)")
    if work.exists():
        subprocess.run(["rm", "-rf", str(work)], check=True)
    work.mkdir(parents=True)
    return exe, fixtures, work


def _sha(path):
    path = pathlib.Path(path)
    if path.is_dir():
        return {str(p): _sha(p) for p in sorted(path.rglob("*")) if p.is_file() and not p.is_symlink()}
    return hashlib.sha256(path.read_bytes()).hexdigest()


_last_rss_mb = 0.0


def run_measured(argv, timeout=300, env=None):
    """Like run(), with the child's own peak RSS (MB) from wait4."""
    global _last_rss_mb
    start = time.monotonic()
    r, w = os.pipe()
    re_, we = os.pipe()
    pid = os.fork()
    if pid == 0:  # child
        devnull = os.open(os.devnull, os.O_RDONLY)
        os.dup2(devnull, 0)
        os.dup2(w, 1)
        os.dup2(we, 2)
        for fd in (r, re_, w, we):
            os.close(fd)
        if env is not None:
            os.execve(str(argv[0]), [str(a) for a in argv], env)
        os.execv(str(argv[0]), [str(a) for a in argv])
    os.close(w)
    os.close(we)
    import selectors
    sel = selectors.DefaultSelector()
    bufs = {r: b"", re_: b""}
    sel.register(r, selectors.EVENT_READ)
    sel.register(re_, selectors.EVENT_READ)
    deadline = start + timeout
    killed = False
    while sel.get_map():
        remaining = deadline - time.monotonic()
        if remaining <= 0 and not killed:
            os.kill(pid, 9)
            killed = True
        for key, _ in sel.select(timeout=max(0.1, remaining)):
            chunk = os.read(key.fd, 65536)
            if not chunk:
                sel.unregister(key.fd)
                os.close(key.fd)
            elif len(bufs[key.fd]) < (1 << 20):
                bufs[key.fd] += chunk
    _, status, usage = os.wait4(pid, 0)
    code = None if killed else (os.waitstatus_to_exitcode(status))
    _last_rss_mb = usage.ru_maxrss / 1024.0
    return code, bufs[r].decode("utf-8", "replace"), bufs[re_].decode("utf-8", "replace"), \
        _last_rss_mb, time.monotonic() - start


def _printable(line):
    return all(ch == "\t" or (ch.isprintable()) for ch in line)


def expect_failure(name, argv, *, exit_code, names, inputs=(), out_dirs=(), forbidden=(),
                   max_rss_mb=600, timeout=300, env=None):
    """One failing run. names: substring(s) the error line must contain (the file);
    inputs: files/folders that must be unchanged; forbidden: paths that must not
    exist afterwards; out_dirs: folders that must hold no temporary files
    (names containing '.tmp')."""
    before = {str(p): _sha(p) for p in inputs}
    code, _, err, rss, secs = run_measured(argv, timeout=timeout, env=env)
    problems = []
    if code != exit_code:
        problems.append(f"exit {code}, expected {exit_code}")
    lines = [l for l in err.splitlines() if l.strip()]
    last = lines[-1] if lines else ""
    if not last.startswith("Error"):
        problems.append(f"last stderr line is not an error: {last!r}")
    for n in ([names] if isinstance(names, str) else names):
        if n not in last:
            problems.append(f"error line does not name {n!r}: {last!r}")
    bad = [l for l in err.splitlines() if not _printable(l)]
    if bad:
        problems.append(f"unprintable stderr: {bad[0]!r}")
    for p in forbidden:
        if os.path.lexists(p):
            problems.append(f"left {p}")
    for d in out_dirs:
        temps = [str(p) for p in pathlib.Path(d).rglob("*") if ".tmp" in p.name]
        if temps:
            problems.append(f"temporary files left: {temps[:3]}")
    for p, h in before.items():
        if not os.path.lexists(p) or _sha(p) != h:
            problems.append(f"input changed: {p}")
    if rss > max_rss_mb:
        problems.append(f"peak memory {rss:.0f} MB > {max_rss_mb} MB")
    _record(name, problems, f"exit {code}, peak {rss:.0f} MB, {secs:.1f} s: {last[:160]}")


def expect_success(name, argv, *, outputs=(), inputs=(), max_rss_mb=600, timeout=300, env=None,
                   stderr_contains=()):
    """One run that must exit 0, create `outputs` and leave `inputs` unchanged."""
    before = {str(p): _sha(p) for p in inputs}
    code, out, err, rss, secs = run_measured(argv, timeout=timeout, env=env)
    problems = []
    if code != 0:
        problems.append(f"exit {code}: {err.strip()[-300:]!r}")
    for p in outputs:
        if not os.path.exists(p):
            problems.append(f"missing output {p}")
    for p, h in before.items():
        if not os.path.lexists(p) or _sha(p) != h:
            problems.append(f"input changed: {p}")
    for s in stderr_contains:
        if s not in err and s not in out:
            problems.append(f"output lacks {s!r}")
    if rss > max_rss_mb:
        problems.append(f"peak memory {rss:.0f} MB > {max_rss_mb} MB")
    _record(name, problems, f"exit {code}, peak {rss:.0f} MB, {secs:.1f} s")


def check(name, ok, detail=""):
    """A free-form assertion (e.g. after a kill)."""
    _record(name, [] if ok else [detail or "failed"], detail)


def _record(name, problems, detail):
    _results.append((name, not problems, detail))
    status = "ok" if not problems else "FAIL: " + "; ".join(problems)
    print(f"{name}: {status} ({detail})", flush=True)


def finish():
    """Prints the summary line and exits 1 if any case failed."""
    passed = sum(1 for _, ok, _ in _results if ok)
    failed = len(_results) - passed
    print(f"reliability: {passed} passed, {failed} failed")
    sys.exit(1 if failed or not _results else 0)
