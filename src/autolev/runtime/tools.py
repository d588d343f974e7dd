"""What the command line uses of the runtime beside the Model, in one place: the
runtime's modules may move without the CLI knowing (the façade of `autolev.cli`)."""
from .numerics.command import program_file_name
from ..engine.files import safe_stem
from ..engine.numbers import parse_number
from ..engine.integrators import METHODS
from ..engine.options import RunOptions
from ..engine.outputs import Written, write_output

__all__ = ["METHODS", "RunOptions", "Written", "parse_number", "program_file_name",
           "safe_stem", "write_output"]
