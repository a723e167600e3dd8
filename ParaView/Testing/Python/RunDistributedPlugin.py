"""The Distributed Feature Points filter under `mpiexec -n 2 pvbatch --mpi` against one process.

  python3 RunDistributedPlugin.py PVBATCH PLUGIN SCRIPT FOLDER

For the project's default detector and the paper's method: the detector's own filter in a plain
pvbatch, then the driver in `mpiexec -n 2 pvbatch --mpi`; every point's FeatureMask and score
must be the same. Exits 125 (the test's SKIP_RETURN_CODE) when something it needs is missing:
mpiexec, pvbatch, the plugin, or a pvbatch that runs with 2 MPI processes.
"""
import os
import shutil
import signal
import subprocess
import sys

SKIP = 125


def skip(why):
    print("skipped: " + why)
    sys.exit(SKIP)


pvbatch, plugin, script, folder = sys.argv[1:5]
mpiexec = shutil.which("mpiexec")
if not mpiexec:
    skip("mpiexec not found (openmpi-bin)")
if not (os.path.isfile(pvbatch) or shutil.which(pvbatch)):
    skip("pvbatch not found: " + pvbatch)
if not os.path.isfile(plugin):
    skip("the plugin is not built: " + plugin)
os.makedirs(folder, exist_ok=True)
launcher = [mpiexec, "--oversubscribe"]
if hasattr(os, "geteuid") and os.geteuid() == 0:
    launcher.append("--allow-run-as-root")  # Open MPI refuses root otherwise (CI containers)


def run(command, timeout=600):
    """The exit code and output of `command`; past `timeout` seconds its whole process group (mpiexec
    and the processes it started) is ended."""
    try:
        child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 universal_newlines=True, preexec_fn=os.setsid)
    except OSError as e:
        return 1, str(e)
    try:
        out, _ = child.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        for sig in (signal.SIGTERM, signal.SIGKILL):
            try:
                os.killpg(child.pid, sig)
            except OSError:
                pass
            try:
                out, _ = child.communicate(timeout=10)
                break
            except subprocess.TimeoutExpired:
                out = ""
        return 1, "timed out after %d s\n%s" % (timeout, out)
    return child.returncode, out


# Can this pvbatch run with 2 MPI processes here? (A ParaView without MPI, or an MPI that cannot
# start 2 processes, is something missing, not a failure of the plugin.)
probe = os.path.join(folder, "probe.txt")
code, text = run(launcher + ["-n", "2", pvbatch, "--mpi", script, "--probe", probe], 120)
if code != 0 or not os.path.isfile(probe):
    shown = text if len(text) <= 4000 else text[:2000] + "\n[...]\n" + text[-2000:]
    skip("mpiexec -n 2 pvbatch --mpi does not run here:\n" + shown)
with open(probe) as f:
    if f.read().strip() != "2":
        skip("pvbatch --mpi under mpiexec -n 2 has no 2 partitions (ParaView without MPI?)")

failed = 0
for method in ("crease", "huang2023"):
    one = os.path.join(folder, method + "-1.txt")
    two = os.path.join(folder, method + "-2.txt")
    for path in (one, two):
        if os.path.exists(path):
            os.remove(path)
    code, text = run([pvbatch, script, plugin, method, "plain", one])
    print(text.strip())
    if code != 0:
        print("FAILED: %s, one process: pvbatch exited with %d" % (method, code))
        failed += 1
        continue
    code, text = run(launcher + ["-n", "2", pvbatch, "--mpi", script, plugin, method, "driver",
                                 two])
    print(text.strip())
    if code != 0:
        print("FAILED: %s, 2 processes: mpiexec exited with %d" % (method, code))
        failed += 1
        continue
    with open(one) as f:
        a = f.read().splitlines()
    with open(two) as f:
        b = f.read().splitlines()
    if b[:1] != ["2"]:
        print("FAILED: %s: the driver ran with %s partitions, not 2" % (method, b[:1]))
        failed += 1
    differ = sum(1 for x, y in zip(a[1:], b[1:]) if x != y)
    if len(a) != len(b) or differ:
        print("FAILED: %s: %d and %d points, %d differ" % (method, len(a) - 1, len(b) - 1, differ))
        failed += 1
    else:
        print("%s: 2 processes give every point the FeatureMask and score of one process (%d points)"
              % (method, len(a) - 1))
sys.exit(1 if failed else 0)
