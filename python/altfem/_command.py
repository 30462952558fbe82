"""The `altfem` executable of this build, for what the module runs as the command line does."""
import subprocess

from . import _core
from ._scene import SceneError
from ._run import NumericalError


def run_command(arguments):
    """Runs `altfem ARGUMENTS...` and returns its standard output; its exit code 2 raises
    SceneError and 3 NumericalError, each with the command's one-line message."""
    completed = subprocess.run([_core.executable()] + [str(argument) for argument in arguments],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if completed.returncode == 0:
        return completed.stdout
    lines = completed.stderr.strip().splitlines()
    message = lines[-1] if lines else f"exit code {completed.returncode}"
    for prefix in ("altfem: error: ", "altfem: numerical failure: "):
        message = message.removeprefix(prefix)
    if completed.returncode == 2:
        raise SceneError(message)
    if completed.returncode == 3:
        raise NumericalError(message)
    raise RuntimeError(f"altfem {' '.join(map(str, arguments))}: exit code {completed.returncode}: {message}")
