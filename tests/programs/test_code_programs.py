"""`autolev code`: the C programs of CODE ALGEBRAIC in the layout of Autolev's, checked
against values derived by hand, against Autolev's own programs from the corpus, and as
the drop-in that csu-hmc/gait2d's cleaning script expects."""
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import autolev
from autolev.cli import main
from autolev.engine.errors import AutolevModelError
from autolev.loader import load_for_run
from autolev.programs import program_texts, write_programs
from autolev.programs.plan import input_file_name, plan_algebraic
from helpers import CORPUS, EXAMPLES, ROOT, SHARED
from helpers import programs as P

needs_cc, needs_octave = P.needs_cc, P.needs_octave

ARM = """\
CONSTANTS L1, L2
VARIABLES Q{2}
X = L1*COS(Q1) + L2*COS(Q1 + Q2)
Y = L1*SIN(Q1) + L2*SIN(Q1 + Q2)
JAC = [D(X, Q1), D(X, Q2); D(Y, Q1), D(Y, Q2)]
TIP = [X; Y]
ENCODE TIP, JAC
CODE ALGEBRAIC() arm_raw.c
"""


def model_from(tmp_path, text, name="arm.al"):
    path = tmp_path / name
    path.write_text(text)
    return autolev.load(path)


def run_program(tmp_path, model, values: dict) -> dict:
    """Our program for the model's first CODE command, compiled and run with `values`
    written into its .in file; {element: value} of its ENCODE arrays."""
    command = model.code_commands[0]
    plan = plan_algebraic(model, command)
    texts = program_texts(model, command)
    source = tmp_path / "ours.c"
    source.write_text(next(t for p, t in texts.items() if p.suffix == ".c"))
    lines = []
    for line in plan.input_text.splitlines():
        name = line[21:42].strip() if len(line) >= 60 and line[58] == "|" else ""
        if name in values:
            line = line[:59] + repr(values[name])
        lines.append(line)
    return P.encoded_values(source, "\n".join(lines) + "\n", input_file_name(command.filename),
                            [(e.name, e.shape) for e in plan.encoded], tmp_path / "run")


@needs_cc
def test_an_algebraic_program_gives_the_values_derived_by_hand(tmp_path):
    model = model_from(tmp_path, ARM)
    l1, l2, q1, q2 = 0.7, 0.4, 0.3, -1.1
    got = run_program(tmp_path, model, {"L1": l1, "L2": l2, "Q1": q1, "Q2": q2})
    # by hand: the tip of a two-link arm and its Jacobian
    want = {"TIP[0]": l1 * math.cos(q1) + l2 * math.cos(q1 + q2),
            "TIP[1]": l1 * math.sin(q1) + l2 * math.sin(q1 + q2),
            "JAC[0][0]": -l1 * math.sin(q1) - l2 * math.sin(q1 + q2),
            "JAC[0][1]": -l2 * math.sin(q1 + q2),
            "JAC[1][0]": l1 * math.cos(q1) + l2 * math.cos(q1 + q2),
            "JAC[1][1]": l2 * math.cos(q1 + q2)}
    assert set(got) == set(want)
    for key, value in want.items():
        assert got[key] == pytest.approx(value, rel=1e-14, abs=1e-15), key


def test_the_program_has_the_sections_downstream_cleaners_search_for(tmp_path):
    model = model_from(tmp_path, ARM)
    text = next(t for p, t in program_texts(model, model.code_commands[0]).items()
                if p.suffix == ".c")
    lines = text.splitlines()
    # autolevclean.py/.c copy eqns1 from here to there, and output() from here to there
    marks = ["/* Evaluate constants */", "/* Evaluate output quantities */",
             "/* Write output to screen and to output file(s) */", "  Encode[0] = 0.0;"]
    where = []
    for mark in marks:
        where.append(lines.index(mark, where[-1] if where else 0))
    copied = lines[where[0]:where[1]] + lines[where[2]:where[3]]
    assert all(len(line) < 100 for line in copied)      # autolevclean.c reads 100 at a time
    # BioMAC's cleaners take z's size from the first 32 characters of its declaration
    declared = next(line for line in lines if line.startswith("double   Pi,"))
    assert declared[:32] == "double   Pi,DEGtoRAD,RADtoDEG,z["
    size = int(re.match(r"\d+", declared[32:]).group())
    used = [int(k) for k in re.findall(r"\bz\[(\d+)\]", "\n".join(copied))]
    assert used and max(used) < size and min(used) >= 1
    # constants first, then variables, each sorted ignoring case (Autolev's read order)
    assert re.search(r"readf\(Fptr\[0\],&L1,&L2,&Q1,&Q2,NULL\);", text)


@needs_cc
def test_the_program_compiles_without_warnings(tmp_path):
    model = model_from(tmp_path, ARM)
    write_programs(model, tmp_path / "out")
    done = subprocess.run([P.compiler(), "-Wall", "-Wextra", "-O2", "-c",
                           str(tmp_path / "out" / "arm_raw.c"), "-o", str(tmp_path / "a.o")],
                          capture_output=True, text=True)
    assert done.returncode == 0 and done.stderr == "", done.stderr


def test_z_slots_are_used_again_once_their_values_are_read():
    from autolev.programs.plan import assign_slots
    # statement k's text reads these statements; the last set is what output() reads
    reads = [set(), {0}, {0, 1}, {2}, {3}, {4}, {5}]
    # by hand: 0 and 1 are free after 2, then 2 after 3, 3 after 4; 5 is kept for output
    assert assign_slots(reads, [True] * 6) == {0: 1, 1: 2, 2: 3, 3: 1, 4: 2, 5: 1}
    # a named quantity takes no slot
    assert assign_slots(reads, [True, False, True, True, True, True]) == \
        {0: 1, 2: 2, 3: 1, 4: 2, 5: 1}


THREE_LINKS = """\
NEWTONIAN N
FRAMES A, B, C
POINTS O, P, R, S
CONSTANTS L{3}
VARIABLES Q{3}'
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
SIMPROT(B, C, 3, Q3)
P_O_P> = L1*A1>
P_P_R> = L2*B1>
P_R_S> = L3*C1>
W_A_N> = Q1'*N3>
W_B_A> = Q2'*A3>
W_C_B> = Q3'*B3>
V_O_N> = 0>
V2PTS(N, A, O, P)
V2PTS(N, B, P, R)
V2PTS(N, C, R, S)
TIP = [DOT(P_O_S>, N1>); DOT(P_O_S>, N2>); DOT(V_S_N>, N1>); DOT(V_S_N>, N2>)]
ENCODE TIP
CODE ALGEBRAIC() links_raw.c
"""


@needs_cc
def test_a_kinematic_chain_program_gives_the_values_derived_by_hand(tmp_path):
    # Z's, repeated and negated subexpressions in z slots used again: the tip of a
    # planar three-link arm and its velocity, by hand
    model = model_from(tmp_path, THREE_LINKS, "links.al")
    v = {"L1": 0.9, "L2": 0.6, "L3": 0.45, "Q1": 0.4, "Q2": -0.8, "Q3": 1.3,
         "Q1'": 0.7, "Q2'": -1.1, "Q3'": 0.25}
    got = run_program(tmp_path, model, v)
    angles = [v["Q1"], v["Q1"] + v["Q2"], v["Q1"] + v["Q2"] + v["Q3"]]
    rates = [v["Q1'"], v["Q1'"] + v["Q2'"], v["Q1'"] + v["Q2'"] + v["Q3'"]]
    lengths = [v["L1"], v["L2"], v["L3"]]
    want = [sum(L * math.cos(a) for L, a in zip(lengths, angles)),
            sum(L * math.sin(a) for L, a in zip(lengths, angles)),
            -sum(L * w * math.sin(a) for L, w, a in zip(lengths, rates, angles)),
            sum(L * w * math.cos(a) for L, w, a in zip(lengths, rates, angles))]
    assert [got[f"TIP[{i}]"] for i in range(4)] == pytest.approx(want, rel=1e-13)


@needs_cc
def test_a_name_the_program_itself_uses_is_renamed(tmp_path):
    # the program's own loop counter: Autolev printed the name and changed its meaning;
    # the model's iloop is written iloop_, said, and the program computes as with L1
    model = model_from(tmp_path, ARM.replace("L1", "iloop"))
    (written,) = write_programs(model, tmp_path / "out")
    assert written.notes == ["arm_raw.c: iloop is written iloop_ in the C program, where "
                             "iloop names something of the program's or C's own"]
    assert "iloop_" in (tmp_path / "out" / "arm_raw.c").read_text()
    l1, l2, q1, q2 = 0.7, 0.4, 0.3, -1.1
    got = run_program(tmp_path, model, {"iloop": l1, "L2": l2, "Q1": q1, "Q2": q2})
    assert got["TIP[0]"] == pytest.approx(l1 * math.cos(q1) + l2 * math.cos(q1 + q2),
                                          rel=1e-14)


def test_programs_are_written_as_the_users_other_files(tmp_path):
    model = model_from(tmp_path, ARM)
    old = os.umask(0o022)
    try:
        write_programs(model, tmp_path / "out")
    finally:
        os.umask(old)
    modes = {p.name: p.stat().st_mode & 0o777 for p in (tmp_path / "out").iterdir()}
    assert modes == {"arm_raw.c": 0o644, "arm_raw.in": 0o644}


def test_a_file_name_leaving_the_output_folder_is_written_inside_it(tmp_path, capsys):
    # `CODE ... ../../escaped.c` was refused by code and accepted by run: both write in
    # --out now (run its files, code its program, by the name's own part) and say so
    path = tmp_path / "arm.al"
    path.write_text(ARM.replace("arm_raw.c", "../../escaped.c"))
    assert main(["code", str(path), "--out", str(tmp_path / "out"), "-q"]) == 0
    assert "its folders lead outside the output folder" in capsys.readouterr().err
    assert sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("escaped*")) \
        == ["out/escaped.c", "out/escaped.in"]


def test_a_code_name_that_is_no_files_is_refused(tmp_path, capsys):
    path = tmp_path / "arm.al"
    path.write_text(ARM.replace("arm_raw.c", "../.c"))
    assert main(["code", str(path), "--out", str(tmp_path / "out"), "-q"]) == 1
    assert "unusable file name in CODE" in capsys.readouterr().err


def test_kinds_not_written_yet_are_reported_and_the_others_written(tmp_path, capsys):
    path = tmp_path / "arm.al"
    path.write_text(ARM + "CODE ALGEBRAIC() arm_raw.f\n")
    assert main(["code", str(path), "--out", str(tmp_path / "out")]) == 1
    captured = capsys.readouterr()
    assert "wrote" in captured.out and "arm_raw.c" in captured.out
    assert "CODE ALGEBRAIC arm_raw.f: programs of this kind in .f are not written yet" \
        in captured.err
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["arm_raw.c", "arm_raw.in"]


def test_a_model_with_errors_writes_nothing(tmp_path, capsys):
    path = tmp_path / "bad.al"
    path.write_text(ARM.replace("X = L1", "X = L3"))
    assert main(["code", str(path), "--out", str(tmp_path / "out")]) == 1
    assert "not declared" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


# -- against Autolev's own programs (the corpus) ---------------------------------------
BIOMAC = CORPUS / "mad-lab-fau+BioMAC-Sim-Toolbox" / "src" / "model"
BIOMAC_427 = CORPUS / ".overlay" / "mad-lab-fau+BioMAC-Sim-Toolbox@427b529d" / "src" / "model"
# each model with the program Autolev wrote from it (the .al at the commit of the program)
AUTOLEV_PROGRAMS = [
    (BIOMAC_427 / "gait2dc/c_files/contact.al", "contact_al_raw.c"),
    (BIOMAC_427 / "gait2dc/c_files/gait2dc_FK.al", "gait2dc_FK_al_raw.c"),
    (BIOMAC_427 / "gait2dc/c_files/gait2dc_stick.al", "gait2dc_stick_al_raw.c"),
    (BIOMAC_427 / "gait2dc/c_files/gait2dc_dynamics.al", "gait2dc_dynamics_al_raw.c"),
    (BIOMAC / "gait2d_osim/c_files/gait2d_osim/gait2d_osim_FK.al", "gait2d_osim_FK_raw.c"),
    (BIOMAC / "gait2d_osim/c_files/gait2d_osim/gait2d_osim_NoDer.al",
     "gait2d_osim_NoDer_raw.c"),
    (BIOMAC / "gait2d_osim/c_files/gait10dof18musc/gait10dof18musc_FK.al",
     "gait10dof18musc_FK_raw.c"),
    (BIOMAC / "gait2d_osim/c_files/gait10dof18musc/gait10dof18musc_NoDer.al",
     "gait10dof18musc_NoDer_raw.c"),
    (BIOMAC / "gait2d_osim/c_files/contact/contact_2d.al", "contact_2d_raw.c"),
    (BIOMAC / "gait3d/c_files/contact/contact_3d.al", "contact_3d_raw.c"),
    pytest.param(BIOMAC / "gait3d/c_files/gait3d_pelvis213/gait3d_pelvis213_FK.al",
                 "gait3d_pelvis213_FK_raw.c", marks=pytest.mark.slow),
    pytest.param(BIOMAC / "gait3d/c_files/gait3d_pelvis213/gait3d_pelvis213_NoDer.al",
                 "gait3d_pelvis213_NoDer_raw.c", marks=pytest.mark.slow),
]


@pytest.mark.corpus
@needs_cc
@pytest.mark.parametrize("model_path, program", AUTOLEV_PROGRAMS,
                         ids=lambda v: v if isinstance(v, str) else "")
def test_encode_values_equal_those_of_autolevs_own_program(model_path, program, tmp_path):
    if not model_path.exists():
        pytest.skip(f"not in the corpus: {model_path}")
    theirs = model_path.parent / program
    model = autolev.load(model_path)
    command = model.code_commands[-1]
    plan = plan_algebraic(model, command)
    ours = tmp_path / "ours.c"
    ours.write_text(next(t for p, t in program_texts(model, command).items()
                         if p.suffix == ".c"))
    arrays = [(e.name, e.shape) for e in plan.encoded]
    template = theirs.with_suffix(".in")
    # Autolev's .in where the corpus has it: both programs read the same lines in order
    template = template.read_text() if template.exists() else plan.input_text
    for draw in range(3):
        text = P.filled_in(template, draw)
        a = P.encoded_values(ours, text, input_file_name(command.filename), arrays,
                             tmp_path / "ours")
        b = P.encoded_values(theirs, text, P.input_name(theirs.read_text(errors="replace")),
                             arrays, tmp_path / "theirs")
        assert set(a) == set(b)
        worst, where = P.largest_difference(a, b)
        assert worst <= 1e-12, f"draw {draw}: {where} differs by {worst:.3g}"


GAIT2D = CORPUS / "csu-hmc+gait2d" / "algait2de"
GAIT2D_GIT = Path(os.environ.get("AUTOLEV_MIRRORS", "/nonexistent")) / "csu-hmc+gait2d" / "repo"

GAIT2D_DRIVER = r"""
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include "gait2de.h"
#define ARGS param_struct *, double *, double *, double *, double *, double *, double *
void gait2d_al_ours(ARGS);
void gait2d_al_theirs(ARGS);
static double draw(void) { return 2.0 * rand() / RAND_MAX - 1.0; }
int main(void)
{
    double worst[3] = {0, 0, 0};
    int lo[3] = {0, NDOF, NDOF + 6}, hi[3] = {NDOF, NDOF + 6, NDOF + 6 + 2 * NSTICK};
    srand(20261124);
    for (int k = 0; k < 1000; k++) {
        param_struct p;
        double *pp = (double *)&p, q[NDOF], qd[NDOF], mom[NDOF];
        double a[NDOF + 6 + 2 * NSTICK], b[NDOF + 6 + 2 * NSTICK];
        for (size_t i = 0; i < sizeof p / sizeof(double); i++) pp[i] = 0.5 + fabs(draw());
        for (int i = 0; i < NDOF; i++) { q[i] = draw(); qd[i] = draw(); mom[i] = 10 * draw(); }
        gait2d_al_ours(&p, q, qd, a, mom, a + NDOF, a + NDOF + 6);
        gait2d_al_theirs(&p, q, qd, b, mom, b + NDOF, b + NDOF + 6);
        for (int g = 0; g < 3; g++) {
            double big = 0, diff = 0;
            for (int i = lo[g]; i < hi[g]; i++) {
                if (isnan(a[i]) || isnan(b[i])) { printf("NaN\n"); return 1; }
                big = fmax(big, fmax(fabs(a[i]), fabs(b[i])));
                diff = fmax(diff, fabs(a[i] - b[i]));
            }
            if (big > 0 && diff / big > worst[g]) worst[g] = diff / big;
        }
    }
    printf("%.17g %.17g %.17g\n", worst[0], worst[1], worst[2]);
    return 0;
}
"""


@pytest.mark.corpus
@needs_cc
def test_gait2d_rebuilds_with_its_own_cleaning_script(tmp_path):
    """csu-hmc/gait2d's autolevclean.py, unchanged, turns our gait2de_al_raw.c into a
    gait2de_al.c that gives the qdd, GRF and Stick of the committed, Autolev-made one."""
    if not (GAIT2D / "gait2de.al").exists():
        pytest.skip("csu-hmc/gait2d is not in the corpus")
    if not GAIT2D_GIT.exists():
        pytest.skip("autolevclean.py and gait2de.h are in the repository's git mirror "
                    "(set AUTOLEV_MIRRORS to the folder of the fetched mirrors)")
    for name in ("autolevclean.py", "gait2de.h"):
        text = subprocess.run(["git", "--git-dir", str(GAIT2D_GIT), "show",
                               f"HEAD:algait2de/{name}"], capture_output=True, text=True,
                              check=True).stdout
        (tmp_path / name).write_text(text)
    assert main(["code", str(GAIT2D / "gait2de.al"), "--out", str(tmp_path), "-q"]) == 0
    subprocess.run([sys.executable, "autolevclean.py", "-i", "gait2de_al_raw.c",
                    "-o", "ours_al.c"], cwd=tmp_path, check=True, capture_output=True)
    shutil.copy(GAIT2D / "gait2de_al.c", tmp_path / "theirs_al.c")
    (tmp_path / "drive.c").write_text(GAIT2D_DRIVER)
    cc = P.compiler()
    for side in ("ours", "theirs"):
        subprocess.run([cc, "-O1", "-c", f"-Dgait2d_al=gait2d_al_{side}", f"{side}_al.c"],
                       cwd=tmp_path, check=True, capture_output=True)
    subprocess.run([cc, "-O1", "-o", "drive", "drive.c", "ours_al.o", "theirs_al.o", "-lm"],
                   cwd=tmp_path, check=True, capture_output=True)
    out = subprocess.run(["./drive"], cwd=tmp_path, capture_output=True, text=True)
    assert out.returncode == 0, out.stdout
    # qdd, GRF, Stick: the largest difference relative to each vector's largest value
    assert all(float(v) <= 1e-12 for v in out.stdout.split()), out.stdout


# -- Matlab --------------------------------------------------------------------------
@needs_octave
def test_a_matlab_program_gives_the_values_derived_by_hand(tmp_path):
    model = model_from(tmp_path, ARM.replace("arm_raw.c", "arm_raw.m"))
    text = next(iter(program_texts(model, model.code_commands[0]).values()))
    rows = {"L1": 0.7, "L2": 0.4, "Q1": 0.3, "Q2": -1.1}
    text = P.with_table_values(text, lambda name: repr(rows[name]) if name in rows else None)
    got = P.octave_encoded(Path("arm_raw.m"), text, ["TIP", "JAC"], tmp_path / "run")
    l1, l2, q1, q2 = 0.7, 0.4, 0.3, -1.1
    # by hand; Matlab's arrays are read column by column
    want = {"TIP[1]": l1 * math.cos(q1) + l2 * math.cos(q1 + q2),
            "TIP[2]": l1 * math.sin(q1) + l2 * math.sin(q1 + q2),
            "JAC[1]": -l1 * math.sin(q1) - l2 * math.sin(q1 + q2),
            "JAC[2]": l1 * math.cos(q1) + l2 * math.cos(q1 + q2),
            "JAC[3]": -l2 * math.sin(q1 + q2),
            "JAC[4]": l2 * math.cos(q1 + q2)}
    assert set(got) == set(want)
    for key, value in want.items():
        assert got[key] == pytest.approx(value, rel=1e-14, abs=1e-15), key


def test_a_matlab_file_name_that_cannot_name_its_function_is_refused(tmp_path):
    model = model_from(tmp_path, ARM.replace("arm_raw.c", "7seg.m"))
    with pytest.raises(AutolevModelError, match="'7seg' cannot name a Matlab function"):
        program_texts(model, model.code_commands[0])


RIDER = CORPUS / "moorepants+RiderModel" / "autolev"


@pytest.mark.corpus
@needs_octave
@pytest.mark.parametrize("stem", ["WhipplePlusRiderLean"])
def test_matlab_encode_values_equal_those_of_autolevs_own_program(stem, tmp_path):
    model_path = RIDER / f"{stem}.AL"
    if not model_path.exists():
        pytest.skip(f"not in the corpus: {model_path}")
    model = autolev.load(model_path)
    command = model.code_commands[-1]
    ours = next(iter(program_texts(model, command).values()))
    theirs = (RIDER / f"{stem}.m").read_text(errors="replace")
    arrays = [e.name for e in plan_algebraic(model, command).encoded]
    program = Path(f"{stem}.m")
    for draw in range(2):
        a = P.octave_encoded(program, P.matlab_with_values(ours, draw), arrays,
                             tmp_path / f"ours{draw}")
        b = P.octave_encoded(program, P.matlab_with_values(theirs, draw), arrays,
                             tmp_path / f"theirs{draw}")
        assert set(a) == set(b)
        worst, where = P.largest_difference(a, b)
        assert worst <= 1e-12, f"draw {draw}: {where} differs by {worst:.3g}"


# -- CODE DYNAMICS in C -----------------------------------------------------------------
@needs_cc
@pytest.mark.parametrize("example", ["double_pendulum", "whipple_benchmark", "rolling_disc",
                                     "nlink_pendulum", "cart_pendulum",
                                     "euler_parameters_body"])
def test_a_dynamics_program_writes_the_files_autolev_run_writes(example, tmp_path):
    """The program integrates with the Kutta-Merson of Autolev's C programs, which
    `autolev run` reproduces (to the digit for the double pendulum's own Autolev
    program, docs/language.md): compiled with -Wall and run from the .in file it
    comes with, it writes the same files byte for byte."""
    model = EXAMPLES / f"{example}.al"
    assert main(["code", str(model), "--out", str(tmp_path / "prog"), "-q"]) == 0
    program = next((tmp_path / "prog").glob("*.c"))
    built = subprocess.run([P.compiler(), "-Wall", "-Wextra", "-O2", "-o", "run",
                            program.name, "-lm"], cwd=tmp_path / "prog",
                           capture_output=True, text=True)
    assert built.returncode == 0 and built.stderr == "", built.stderr
    ran = subprocess.run(["./run"], cwd=tmp_path / "prog", capture_output=True, text=True)
    assert ran.returncode == 0, ran.stdout
    assert main(["run", str(model), "--out", str(tmp_path / "run"), "-q"]) == 0
    ours = sorted(p.name for p in (tmp_path / "run").glob(f"{program.stem}.[0-9]*"))
    assert ours
    for name in ours:
        written = (tmp_path / "prog" / name).read_bytes()
        assert written == (tmp_path / "run" / name).read_bytes(), name


def test_a_dynamics_program_reads_constants_initial_values_and_integration_parameters(
        tmp_path):
    model = EXAMPLES / "double_pendulum.al"
    texts = program_texts(autolev.load(model), autolev.load(model).code_commands[0])
    text = next(t for p, t in texts.items() if p.suffix == ".c")
    groups = re.findall(r"/\* Read ([^*]+) \*/\n(readf\([^;]*;)", text)
    assert [g[0].strip() for g in groups] == [
        "values of constants from input file",
        "the initial value of each variable from input file",
        "integration parameters from input file"]
    assert "&TINITIAL,&TFINAL,&INTEGSTP,&_printint,&abserr,&relerr" in groups[2][1]
    infile = next(t for p, t in texts.items() if p.suffix == ".in")
    # each group ends with the line readf consumes after it (a blank line, then dashes)
    assert infile.count("\n\n") >= 2


# -- CODE DYNAMICS in Matlab, against the reference runs of Autolev's programs ------------
def _truth_matlab_runs():
    import csv
    index = SHARED / "truth" / "index.tsv"
    if not index.exists():
        return []
    return [(r["id"], r["run"]) for r in csv.DictReader(open(index), delimiter="\t")
            if r["kind"] == "m" and r["status"].startswith("ok") and r["run"] != "-"
            and (SHARED / "truth" / r["id"] / r["run"] / "inputs.txt").exists()]


@pytest.mark.corpus
@needs_octave
@pytest.mark.parametrize("ident, run", _truth_matlab_runs())
def test_a_matlab_dynamics_program_writes_the_reference_runs_files(ident, run, tmp_path):
    """Our .m program, given the input values of the reference run, run under GNU
    Octave (as the reference runs of Autolev's own programs were) writes their files:
    the same rows to the printed digits."""
    sys.path.insert(0, str(ROOT / "bench"))
    from corpus import corpus_models
    path = dict(corpus_models(CORPUS)).get(ident)
    if path is None:
        pytest.skip(f"{ident}: not in the corpus")
    model, _ = load_for_run(path)      # statements after the CODE do not matter to it
    commands = [c for c in model.code_commands
                if c.kind == "dynamics" and c.filename.lower().endswith(".m")]
    if not commands:
        pytest.skip(f"{ident}: no CODE DYNAMICS into a .m file")
    text = next(iter(program_texts(model, commands[0]).values()))
    reference = SHARED / "truth" / ident / run
    values = dict(re.findall(r"^(\w+) = (.*?)\s+%", (reference / "inputs.txt").read_text(),
                             re.M))
    stem = Path(commands[0].filename).stem
    (tmp_path / f"{stem}.m").write_text(P.with_table_values(text, values.get))
    done = P.run_octave(stem, tmp_path)
    compared = 0
    written = {p.name.lower(): p for p in tmp_path.glob(f"{stem}.[0-9]*")}
    # the reference programs' files carry their repository's spelling of the name
    for ref in sorted(p for p in reference.iterdir() if p.name.lower().startswith(
            stem.lower() + ".") and p.suffix[1:].isdigit()):
        ours = written.get(ref.name.lower())
        assert ours is not None, done.stdout[-500:] + done.stderr[-500:]
        a, b = P.table_rows(ours), P.table_rows(ref)
        if len(b[0]) != len(a[0]):
            continue          # Autolev wrote no columns for an OUTPUT matrix (README)
        assert len(a) == len(b), ref.name
        # each column to the printed digits of its largest value, or of a millionth of
        # the file's largest for a column that is zero up to round-off (bench/truth.py)
        whole = max(abs(v) for row in b for v in row)
        for col in range(len(b[0])):
            scale = max(max(abs(row[col]) for row in b), 1e-6 * whole) or 1.0
            worst = max(abs(x[col] - y[col]) for x, y in zip(a, b))
            assert worst <= 1e-6 * scale, f"{ref.name} column {col + 1}: {worst:.3g}"
        compared += 1
    assert compared, f"no file compared: {sorted(p.name for p in tmp_path.iterdir())}"


def test_a_dynamics_program_of_a_model_without_states_is_refused(tmp_path, capsys):
    path = tmp_path / "arm.al"
    path.write_text(ARM.replace("CODE ALGEBRAIC() arm_raw.c", "CODE DYNAMICS() arm.c"))
    assert main(["code", str(path), "--out", str(tmp_path / "out")]) == 1
    assert "the model has no state to integrate" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_an_output_column_that_is_exactly_zero_is_passed_to_writef_as_a_double():
    from autolev.programs.c import output_lines
    lines = output_lines([[(0, "NOTHING", None), (1, "ONE", None)]], [], ["0", "1.0"])
    assert lines == ['  writef(stdout, " %- 14.6E", 0.0,1.0,_NAN);',
                     '  writef(Fptr[1], " %- 14.6E", 0.0,1.0,_NAN);']


def test_a_model_autolev_code_built_is_kept_in_the_cache_of_built_models(tmp_path,
                                                                         monkeypatch):
    from autolev.engine import cachekeys
    from autolev import modelcache
    monkeypatch.setenv("AUTOLEV_CACHE", str(tmp_path / "cache"))
    monkeypatch.delenv(cachekeys.DISABLE_VARIABLE, raising=False)
    path = tmp_path / "arm.al"
    path.write_text(ARM)
    assert main(["code", str(path), "--out", str(tmp_path / "out"), "-q"]) == 0
    assert len(list((tmp_path / "cache").glob(modelcache.PREFIX + "*.pickle"))) == 1


def test_each_named_quantity_says_which_statement_of_the_model_defines_it(tmp_path):
    model = tmp_path / "double_pendulum.al"
    model.write_text((EXAMPLES / "double_pendulum.al").read_text().replace(
        "Q2' = U2", "Q2' = U2  % a */ b"))
    assert main(["code", str(model), "--out", str(tmp_path / "out"), "-q"]) == 0
    lines = (tmp_path / "out" / "double_pendulum.c").read_text().splitlines()
    at = lines.index("/* double_pendulum.al:20: Q1' = U1 */")
    assert lines[at + 1] == "  Q1p = U1;"
    # the statement without its comment; text from outside never ends the C comment
    at = lines.index("/* double_pendulum.al:21: Q2' = U2 */")
    assert lines[at + 1] == "  Q2p = U2;"
    from autolev.programs.c import c_comment
    assert c_comment("X = 1 */ Y \u00e9") == "/* X = 1 * / Y ? */"


@needs_cc
@pytest.mark.parametrize("name", ["gamma", "index", "j0", "y1", "hypot", "y0", "j1", "erf",
                                  "nan", "stdin", "M_PI", "unix"])
def test_a_name_the_c_library_declares_is_renamed_and_compiles(tmp_path, capsys, name):
    # glibc's headers declare these in gcc's default mode: the program would not compile
    # with them (it was refused); written NAME_, it compiles and computes Y = K*NAME
    path = tmp_path / "lib.al"
    path.write_text(f"CONSTANTS {name}, K\nY = K*{name}\nINPUT K=2, {name}=3\nOUTPUT Y\n"
                    "CODE ALGEBRAIC() lib.c\n")
    assert main(["code", str(path), "--out", str(tmp_path / "out")]) == 0
    assert f"{name} is written {name}_ in the C program" in capsys.readouterr().err
    out = tmp_path / "out"
    done = subprocess.run([P.compiler(), "-Wall", "-o", "lib", "lib.c", "-lm"], cwd=out,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    subprocess.run(["./lib"], cwd=out, capture_output=True, check=True)
    assert float((out / "lib.1").read_text().split()[-1]) == pytest.approx(6.0)


@needs_cc
def test_the_same_names_in_another_case_compile(tmp_path, capsys):
    # C tells case apart: Gamma, Y1 and Index are the model's own
    path = tmp_path / "case.al"
    path.write_text("CONSTANTS Gamma, Y1, Index\nY = Gamma*Y1 + Index\n"
                    "INPUT Gamma=2, Y1=3, Index=4\nOUTPUT Y\nCODE ALGEBRAIC() case.c\n")
    assert main(["code", str(path), "--out", str(tmp_path / "out")]) == 0
    done = subprocess.run([P.compiler(), "-Wall", "-o", "case", "case.c", "-lm"],
                          cwd=tmp_path / "out", capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


PENDULUM_RATES = """
NEWTONIAN N
FRAMES A
VARIABLES theta', omega'
CONSTANTS L, G
SIMPROT(N, A, 3, theta)
theta' = omega
omega' = -G/L*SIN(theta)
ENCODE theta', omega'
CODE ALGEBRAIC() penalg.c
"""


@needs_cc
def test_an_encoded_derivative_is_named_as_the_program_names_it(tmp_path):
    # ENCODE theta', omega': the program declared `double theta'` (10 compiler errors);
    # the arrays are thetap and omegap, which the program computes by those names
    model = model_from(tmp_path, PENDULUM_RATES, "penalg.al")
    assert [e.name for e in plan_algebraic(model, model.code_commands[0]).encoded] == \
        ["thetap", "omegap"]
    l, g, theta, omega = 0.8, 9.81, 0.3, 0.2
    got = run_program(tmp_path, model, {"L": l, "G": g, "theta": theta, "omega": omega})
    assert got["thetap"] == pytest.approx(omega, rel=1e-15)
    assert got["omegap"] == pytest.approx(-g / l * math.sin(theta), rel=1e-15)


def test_an_encoded_expression_without_a_name_is_refused_before_writing(tmp_path):
    model = model_from(tmp_path, PENDULUM_RATES.replace("ENCODE theta', omega'",
                                                        "ENCODE theta + omega"), "p.al")
    with pytest.raises(AutolevModelError, match="give the expression a name first"):
        plan_algebraic(model, model.code_commands[0])


MATLAB_NAMES = """
VARIABLES q'
MOTIONVARIABLES' u'
CONSTANTS gamma, L, g, VAR, Index
q' = u
u' = -g/L*SIN(q) - gamma*u + Index*VAR
INPUT gamma = 0.3, L = 1, g = 9.81, VAR = 0.5, Index = 0.1, q = 0.4, u = 0
INPUT TFINAL = 1, INTEGSTP = 0.1
OUTPUT q, u, gamma
CODE ODE() swing.m
"""


def test_matlab_names_are_renamed_only_where_they_break_the_program(tmp_path):
    # gamma (a function the program may call), u (its S-function's argument) and VAR
    # (its state) are renamed, with a note; Index and L are Matlab's to keep (Matlab
    # tells case apart): they were refused in any case
    model = model_from(tmp_path, MATLAB_NAMES, "swing.al")
    (written,) = write_programs(model, tmp_path / "out")
    assert sorted(n.split(":")[1].split()[0] for n in written.notes) == \
        ["VAR", "gamma", "u"]
    text = (tmp_path / "out" / "swing.m").read_text()
    assert "global   g gamma_ Index L VAR_;" in text and "global   q u_;" in text
    if P.octave() is None:
        pytest.skip("GNU Octave runs the Matlab program; it is not installed")
    ran = P.run_octave("swing", tmp_path / "out")
    assert ran.returncode == 0, ran.stderr
    # its columns q, u, gamma (no T: the OUTPUT has none), printed to 7 digits
    ours = np.loadtxt(tmp_path / "out" / "swing.1", comments="%")
    rows = autolev.load(tmp_path / "swing.al").simulate().outputs[0]
    for k, name in enumerate(["q", "u", "gamma"]):
        assert np.allclose(ours[:, k], rows[name], rtol=1e-6, atol=1e-6), name
