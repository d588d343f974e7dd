"""What the command line uses of the runtime beside the Model, in one place: the
runtime's modules may move without the CLI knowing (the façade of `autolev.cli`)."""
from .numerics.command import program_file_name
from .numerics.files import safe_stem
from .numerics.numbers import parse_number
from .numerics.options import METHODS, RunOptions
from .numerics.prepare import keep_built
from .outputs import Written, write_output

__all__ = ["METHODS", "RunOptions", "Written", "keep_built", "parse_number",
           "program_file_name", "safe_stem", "write_output"]
