"""Run cad2osmag algorithms headless through scripts/qgis-process (a subprocess) in tests."""
import json
import subprocess

from .conftest import REPO

SCRIPT = str(REPO / "scripts" / "qgis-process")


def run_alg(alg, params, timeout=600, check=True):
    """Run ``cad2osmag:<alg>`` with ``params`` (dict; list values repeat the parameter).

    Returns (returncode, results dict or None, combined output). With ``check`` a non-zero exit fails
    with the tool's output in the message.
    """
    args = [SCRIPT, "--json", "run", f"cad2osmag:{alg}", "--"]
    for key, value in params.items():
        for v in (value if isinstance(value, (list, tuple)) else [value]):
            args.append(f"{key}={v}")
    proc = subprocess.run(args, capture_output=True, text=True, timeout=timeout, stdin=subprocess.DEVNULL)
    output = proc.stdout + proc.stderr
    results = None
    start = proc.stdout.find("{")
    if proc.returncode == 0 and start >= 0:
        try:
            results = json.loads(proc.stdout[start:]).get("results")
        except ValueError:
            results = None
    if check:
        assert proc.returncode == 0, f"cad2osmag:{alg} failed:\n{output[-4000:]}"
    return proc.returncode, results, output
