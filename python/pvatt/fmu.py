"""The interface of any FMI 2.0 FMU (as `cosim info`)."""

from .system import System


class Fmu:
    def __init__(self, path):
        self.path = path
        self._system = System(path, fmu_dirs=[])
        (self.name,) = self._system.components

    def info(self):
        """{"name": ..., "variables": {name: Variable}} with types, causality, units, start values and
        an Enumeration's items."""
        return {"name": self.name, "variables": dict(self._system.components[self.name])}

    def system(self):
        """The FMU as a one-component system (to run it, step it or set its parameters)."""
        return self._system
