"""The Autolev session's own statements: settings (DEGREES, AUTORHS, COMPLEX, ...), RUN
of a file, macro calls and EXIT; nothing of the model but what the settings change."""
from __future__ import annotations

from .. import ir
from .core import STATEMENTS, Translator
from .emit import comment, quote


@STATEMENTS.register(ir.Run)
def run(tr: Translator, st: ir.Run) -> None:
    tr.emit(f"# (the statements of {comment(st.filename)} follow)")


@STATEMENTS.register(ir.MacroCall)
def macro(tr: Translator, st: ir.MacroCall) -> None:
    tr.emit(f"# (macro {comment(st.name)}: its statements follow)")


@STATEMENTS.register(ir.Exit)
def exit_statement(tr: Translator, st: ir.Exit) -> None:
    tr.emit("# (EXIT ends the Autolev session)")
    tr.session.exited = True


@STATEMENTS.register(ir.Setting)
def setting(tr: Translator, st: ir.Setting) -> None:
    if st.name == "DEGREES":
        tr.session.degrees = st.value != "OFF"
    elif st.name == "AUTORHS":
        tr.session.autorhs = st.value in ("ON", "ALL")
    value = "None" if st.value is None else quote(st.value)
    tr.emit(f"model.setting({quote(st.name)}, {value})")

