"""altfem.Scene: a scene file or dict, validated exactly as the command line does."""
import copy
import json
import os

from . import _core

SceneError = _core.SceneError
SceneError.__doc__ = "Bad input: the message is the command line's one line, 'file: /key: what was expected'."


class Scene:
    """A scene (docs/scene-schema.md) and the assignments made to it with `set`.

    Scene(document) takes a dict; Scene.load(path) reads a file. Either is validated at
    once and after every `set`: bad input raises SceneError with the message
    `altfem run` prints, e.g. "<scene dict>: /material/poisson_ratio: must be < 0.5, got 0.5".
    Relative paths in a dict are taken from the current folder (or from `base`).
    """

    def __init__(self, document, *, base=None, name="<scene dict>"):
        if not isinstance(document, dict):
            raise TypeError(f"Scene(document): expected a dict, got {type(document).__name__}")
        self._file = os.path.join(os.path.abspath(base), name) if base else name
        self._text = json.dumps(document)
        self._assignments = []
        self._resolved = self._resolve([])

    @classmethod
    def load(cls, path):
        """The scene in the JSON file `path` (paths in it relative to its folder)."""
        scene = cls.__new__(cls)
        scene._file = os.fspath(path)
        scene._text = ""
        scene._assignments = []
        scene._resolved = scene._resolve([])
        return scene

    def set(self, key, value):
        """Sets the JSON pointer `key` ("discretization/fem/element") to `value`, as
        `altfem run --set KEY=VALUE` does; returns the scene. Raises SceneError and leaves
        the scene unchanged when the result is not a valid scene."""
        assignment = f"{key}={json.dumps(value)}"
        resolved = self._resolve(self._assignments + [assignment])
        self._assignments.append(assignment)
        self._resolved = resolved
        return self

    def copy(self):
        """An independent copy: `set` on it leaves this scene as it is."""
        return copy.deepcopy(self)

    def resolved(self, method=None):
        """The scene with every default filled in and paths absolute, as a dict (what
        summary.json's `options` holds); with `method`, its discretization block too."""
        if method is None:
            return json.loads(self._resolved)
        return json.loads(self._resolve(self._assignments, [method]))

    @property
    def name(self):
        return self.resolved()["name"]

    def _resolve(self, assignments, methods=()):
        return _core.resolve_scene(self._file, self._text, assignments, list(methods))

    def _source(self):
        """The arguments _core.run takes for this scene."""
        return self._file, self._text, list(self._assignments)

    def _file_for_commands(self, folder):
        """A scene file the `altfem` executable can read: the scene's own file when
        nothing was set, else the resolved scene (absolute paths) written into `folder`."""
        if not self._text and not self._assignments:
            return self._file
        path = os.path.join(folder, "scene.json")
        with open(path, "w") as file:
            json.dump(json.loads(self._resolved), file, indent=2)
        return path

    def __repr__(self):
        sets = "".join(f" --set {assignment}" for assignment in self._assignments)
        return f"<altfem.Scene {self._file}{sets}>"


def as_scene(value):
    """`value` itself when it is a Scene, else the scene file it names (str or path)."""
    return value if isinstance(value, Scene) else Scene.load(value)
