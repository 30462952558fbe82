"""What bench/petsc_study.py and bench/petsc_refinement.py share: their common arguments
and one `altfem run` of a static solve to a relative residual of 1e-8, read back from its
summary.json."""
import argparse
import json
import pathlib
import subprocess

ROOT = pathlib.Path(__file__).resolve().parent.parent


def arguments(description, out_name, *more):
    """The parsed command line: --altfem, --out, --largest, --problem, and `more`, each an
    (argparse flags, keywords) pair."""
    parser = argparse.ArgumentParser(description=description, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default=ROOT / "build/bin/altfem")
    parser.add_argument("--out", default=ROOT / "out" / out_name, type=pathlib.Path)
    parser.add_argument("--largest", action="store_true")
    parser.add_argument("--problem", default="", help="only the problems whose label holds this text")
    for flags, keywords in more:
        parser.add_argument(*flags, **keywords)
    return parser.parse_args()


def run(altfem, scene, method, settings, out):
    """(summary, "") of the run, its peak resident set in GB as summary["peak_gb"], or
    (None, the last line of its error)."""
    rss = pathlib.Path(str(out) + ".rss")
    command = ["/usr/bin/time", "-f", "%M", "-o", str(rss), str(altfem), "run", str(scene), "--method", method,
               "--out", str(out), "--set", "solver/linear_tolerance=1e-8", "--set", "output/volume=false"]
    for setting in settings:
        command += ["--set", setting]
    out.parent.mkdir(parents=True, exist_ok=True)
    finished = subprocess.run(command, capture_output=True, text=True)
    if finished.returncode != 0:
        return None, finished.stderr.strip().splitlines()[-1]
    summary = json.loads((out / "summary.json").read_text())
    summary["peak_gb"] = int(rss.read_text().split()[-1]) / 2**20
    return summary, ""
