"""Reading files: encodings, macros (NAME.A), RUN includes and the line map."""
import os

import pytest

import autolev
from autolev import ir
from autolev.source import SourceFile, decode, mapped_source


def write(path, text, encoding="utf-8"):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(text.encode(encoding))
    return path


def diagnostics(path):
    with pytest.raises(autolev.AutolevSyntaxError) as info:
        autolev.parse(path)
    return [d for d in info.value.diagnostics if d.severity == "error"]


def test_decode_utf8_bom_utf16_and_latin1():
    assert decode("% é\nx = 1".encode("utf-8")) == "% é\nx = 1"
    assert decode(b"\xef\xbb\xbfx = 1") == "x = 1"
    assert decode("x = 1".encode("utf-16")) == "x = 1"
    assert decode("% café\nx = 1".encode("latin-1")) == "% café\nx = 1"


def test_latin1_file_and_upper_case_extension(tmp_path):
    f = write(tmp_path / "MODEL.AL", "% Müller's model\nCONSTANTS a\nb = a\n", "latin-1")
    p = autolev.parse(f)
    assert [s.kind for s in p.statements] == ["declaration", "assignment"]
    assert p.filename == str(f)


def test_line_map_points_into_original_lines_after_continuation():
    src = SourceFile("m.al", "a = 1 + &\n      2 +&\n  $\n")
    m = mapped_source(src)
    assert m.text == "a = 1 + 2 +$\n"
    off = m.text.index("$")
    loc = m.locate(off)
    assert (loc.line, loc.col) == (3, 3)
    assert m.source_line(off) == "  $"


def test_error_after_continuation_reports_the_physical_line(tmp_path):
    f = write(tmp_path / "m.al", "x = a + &\n    b +\n")
    (d,) = diagnostics(f)
    assert (d.line, d.col) == (2, 8) and d.source_line == "    b +"


MACRO = """% force on a point
y#1# = dot(P_NO_#1#>, N2>)
Force_#1#> += -k*y#1#*N2>
"""


def test_macro_expansion(tmp_path):
    write(tmp_path / "contact.a", MACRO)
    f = write(tmp_path / "walk.al", "NEWTONIAN N\nPOINTS Heel, Toe\ncontact(Heel)\ncontact(Toe)\n")
    p = autolev.parse(f)
    kinds = [s.kind for s in p.statements]
    assert kinds == ["declaration", "declaration", "macro", "assignment", "assignment",
                     "macro", "assignment", "assignment"]
    assert p.statements[3].target == ir.Name("yHeel")
    assert p.statements[7].target == ir.VectorName("Force_Toe")
    call = p.statements[2]
    assert call.name == "contact" and call.args == ("Heel",)
    # spans of expanded statements point into the macro file, via the call
    span = p.statements[4].span
    assert span.file.endswith("contact.a") and span.line == 3
    assert span.start.via.line == 3 and span.start.via.file.endswith("walk.al")


def test_macro_file_found_in_any_case(tmp_path):
    write(tmp_path / "EXTFORCE.A", "Force_#1#> += F*N1>\n")
    f = write(tmp_path / "m.al", "NEWTONIAN N\nPOINTS P\nExtForce(P)\n")
    assert [s.kind for s in autolev.parse(f).statements][-2:] == ["macro", "assignment"]


def test_macro_with_two_arguments_and_glued_unit_vector(tmp_path):
    write(tmp_path / "acc.a", "P_#2#_X#1#> := a*#1#1> + b*#1#2>\n")
    f = write(tmp_path / "m.al", "acc(Trunk, Hip)\n")
    st = autolev.parse(f).statements[-1]
    assert st.target == ir.VectorName("P_Hip_XTrunk")
    assert st.value.left.right == ir.VectorName("Trunk1")


def test_error_inside_a_macro_points_at_the_macro_line_and_the_call(tmp_path):
    write(tmp_path / "bad.a", "% line 1\nx#1# = (1 +\n")
    f = write(tmp_path / "m.al", "a = 1\nbad(Q)\n")
    (d,) = diagnostics(f)
    assert d.file.endswith("bad.a") and d.line == 2
    assert d.location.via.line == 2 and d.location.via.file.endswith("m.al")
    text = d.format()
    assert "in macro bad(Q)" in text


def test_macro_column_of_substituted_text(tmp_path):
    write(tmp_path / "bad.a", "z = #1# $\n")
    f = write(tmp_path / "m.al", "bad(LongArgument)\n")
    (d,) = diagnostics(f)
    # '$' is at column 9 of the macro line, whatever the argument's length
    assert (d.line, d.col) == (1, 9)


def test_macro_with_too_few_arguments(tmp_path):
    write(tmp_path / "two.a", "x = #1# + #2#\n")
    f = write(tmp_path / "m.al", "two(a)\n")
    (d,) = diagnostics(f)
    assert d.code == "E030" and "#2#" in d.message


def test_macro_that_calls_itself(tmp_path):
    write(tmp_path / "loop.a", "loop(#1#)\n")
    f = write(tmp_path / "m.al", "loop(a)\n")
    (d,) = diagnostics(f)
    assert d.code == "E031"


def test_macros_and_functions_linked_outside_the_model_folder_are_refused(tmp_path):
    secret = write(tmp_path / "secret" / "passwd", "root:x:0:0:SECRET-TEXT\n")
    model = tmp_path / "model"
    model.mkdir()
    (model / "leak.a").symlink_to(secret)
    (model / "leakf.r").symlink_to(secret)
    f = write(model / "m.al", "CONSTANTS A\nLEAK()\nX = LEAKF(A)\n")
    found = diagnostics(f)
    assert [d.code for d in found] == ["E025", "E025"]
    assert all("SECRET-TEXT" not in (d.message + (d.source_line or "")) for d in found)
    # each says which of the model's files is the link (not only the call's name)
    assert ["leak.a" in found[0].message, "leakf.r" in found[1].message] == [True, True]


def test_run_includes_a_file(tmp_path):
    write(tmp_path / "kin.al", "NEWTONIAN N\nBODIES A\n")
    f = write(tmp_path / "dyn.al", "RUN kin.al\nMASS A = m\n")
    p = autolev.parse(f)
    assert [s.kind for s in p.statements] == ["run", "declaration", "declaration", "mass"]
    assert p.symbols.entity("A").kind == "body"
    assert any(name.endswith("kin.al") for name in p.files)


def test_run_relative_to_a_parent_folder_and_backslash(tmp_path):
    # RUN paths were relative to Autolev's working folder, sometimes the model's parent
    write(tmp_path / "sub" / "kin.al", "NEWTONIAN N\n")
    f = write(tmp_path / "sub" / "dyn.al", "RUN sub\\KIN.AL\n")
    p = autolev.parse(f)
    assert p.statements[0].path == str((tmp_path / "sub" / "kin.al").resolve())


def test_run_refuses_paths_leaving_the_model_folder(tmp_path):
    write(tmp_path / "x.al", "NEWTONIAN N\n")
    f = write(tmp_path / "a" / "b" / "m.al", "RUN ../../x.al\n")
    (d,) = diagnostics(f)
    assert d.code == "E021" and "refused" in d.message
    f2 = write(tmp_path / "a" / "m2.al", f"RUN {tmp_path / 'x.al'}\n")
    (d,) = diagnostics(f2)
    assert d.code == "E021"


def test_run_of_a_missing_file(tmp_path):
    f = write(tmp_path / "m.al", "RUN nothere.al\n")
    (d,) = diagnostics(f)
    assert d.code == "E022" and d.col == 5


def test_run_cycle(tmp_path):
    write(tmp_path / "a.al", "RUN b.al\n")
    write(tmp_path / "b.al", "RUN a.al\n")
    (d,) = diagnostics(tmp_path / "a.al")
    assert d.code == "E023"


def test_run_in_text_without_a_file():
    with pytest.raises(autolev.AutolevSyntaxError) as info:
        autolev.parse("RUN kin.al\n")
    assert info.value.diagnostics[0].code == "E020"


def test_error_in_a_run_file_names_that_file(tmp_path):
    write(tmp_path / "kin.al", "NEWTONIAN N\nx = )\n")
    f = write(tmp_path / "dyn.al", "% dynamics\nRUN kin.al\n")
    (d,) = diagnostics(f)
    assert os.path.basename(d.file) == "kin.al" and d.line == 2
    assert d.location.via.line == 2


def test_missing_file_raises_file_error(tmp_path):
    with pytest.raises(autolev.AutolevFileError):
        autolev.parse(tmp_path / "none.al")
