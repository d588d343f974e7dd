"""The error the runtime raises when a model asks for something it cannot do."""


class AutolevModelError(Exception):
    """A model cannot do what a statement asks (missing mass, velocity, ...)."""


class MissingValues(AutolevModelError):
    """Constants a run needs have no value (raised before anything is compiled);
    `names`: their names as the model spells them."""

    def __init__(self, message: str, names=()):
        super().__init__(message)
        self.names = tuple(names)
