"""A CODE command's program in C, section for section in the layout of Autolev 4.1's
programs: the global names, the section comments that downstream scripts search for
(autolevclean.py, BioMAC's clean_*.c), main / eqns1 / output / readf / pgets / writef,
and the NAME.in file main() reads."""
from __future__ import annotations

import re
from pathlib import Path

from .. import __version__
from ..runtime import units
from ..engine.files import header as output_header
from ..runtime.printer import CPrinter
from .plan import (Plan, c_name, rename_clashes, element_indices, input_file_name, printed,
                   program_name, shown_values, with_sources)

# C's keywords, as spelt (C tells case apart)
KEYWORDS = frozenset("""
auto break case char const continue default do double else enum extern float for goto
if inline int long register restrict return short signed sizeof static struct switch
typedef union unsigned void volatile while
""".split())
# the program's own names, as spelt, where the model's quantities are read and written
# (main, eqns1, output): its functions, globals and their locals
OWN_NAMES = frozenset("""
main eqns1 output readf pgets writef z Encode Pi DEGtoRAD RADtoDEG _NAN Fptr fileName
iloop
""".split())



def _library_names() -> frozenset:
    lines = (Path(__file__).parent / "c_library_names.txt").read_text().splitlines()
    return frozenset(line.strip() for line in lines if line.strip()
                     and not line.startswith("#"))


# what the headers the programs include declare (gamma, j0, y1, index, stdin, M_PI, ...)
LIBRARY_NAMES = _library_names()

LINE = 78            # continuation lines start with two spaces; lines stay well under 100
_TOKEN = re.compile(r"\s*([A-Za-z_][A-Za-z_0-9]*(?:\[[0-9]+\])*|[0-9.]+(?:[eE][-+]?[0-9]+)?"
                    r"|&[A-Za-z_][A-Za-z_0-9]*|.)")


def wrap(head: str, text: str, tail: str = ";") -> list[str]:
    """`head + text + tail` as lines of at most LINE characters where it can be:
    broken before a name or number, never inside one (a cleaner that rewrites par__
    names line by line must see each name whole)."""
    lines, line = [], head
    for m in _TOKEN.finditer(text):
        token = m.group(1)
        spaced = m.group(0)
        if len(line) + len(spaced) > LINE and line.strip() and \
                (token[0].isalnum() or token[0] in "_&("):
            lines.append(line.rstrip())
            line = "  " + token
        else:
            line += spaced
    lines.append(line + tail)
    return lines


def c_string(text: str, fmt: bool = False) -> str:
    """`text` as the body of a C string literal; `fmt`: of a printf format (that
    prints `text` as it is)."""
    out = []
    for ch in text:
        if ch == "%" and fmt:
            out.append("%%")
        elif ch in '"\\':
            out.append("\\" + ch)
        elif ch == "\n":
            out.append("\\n")
        elif " " <= ch <= "~":
            out.append(ch)
        else:
            out.append("".join(f"\\{b:03o}" for b in ch.encode("utf-8")))
    return "".join(out)


# names a program that solves equations or sweeps an input uses besides
SOLVING_NAMES = frozenset("COEF RHS SOL solve abserr relerr iter ipoint converged".split())


class CProgram:
    """The text of one plan's C program."""

    def __init__(self, plan: Plan):
        rename_clashes(plan, KEYWORDS | OWN_NAMES | LIBRARY_NAMES
                       | (SOLVING_NAMES if plan.solves_or_sweeps() else frozenset()), "C")
        self.plan = plan
        self.name = program_name(plan.filename)
        self.stem = self.name.rpartition(".")[0] or self.name
        self.unknowns, self.computed = plan.unknowns, plan.computed
        self.where = {s: plan.name_of(s) for s in plan.inputs + plan.specified + plan.named
                      + self.computed}
        self.nfiles = len(plan.files)

    def text(self) -> str:
        computed, written = self._computation()
        lines = (self._top() + self._main() + ["", ""] + self._eqns1(computed) + ["", ""]
                 + self._output(written) + ["", ""])
        if self.unknowns:
            lines += SOLVE + ["", ""]
        return "\n".join(lines + READING_AND_WRITING) + "\n"

    # -- the computation ----------------------------------------------------------------
    def _computation(self) -> tuple[list, list]:
        """(eqns1's statements, output()'s) as lines, intermediates in z slots."""
        p = self.plan
        part = printed(p.statements, shown_values(p), self.where,
                       CPrinter, lambda k: f"z[{k}]", name_of=p.name_of)
        self.z_size = part.top
        computed = _lines(part, p.sources)
        if p.solving is not None:
            computed = self._solution() + [""] + computed
        return computed, output_lines(p.files, p.encoded, part.values)

    def _solution(self) -> list[str]:
        """eqns1's solution of the equations for the unknowns, before the outputs."""
        solving, n = self.plan.solving, len(self.unknowns)
        part = printed(solving.statements, solving.matrix + solving.right, self.where,
                       CPrinter, lambda k: f"z[{k}]", name_of=self.plan.name_of)
        self.z_size = max(self.z_size, part.top)
        matrix, right = part.values[:n * n], part.values[n * n:]
        body = _lines(part, self.plan.sources)
        for i in range(n):
            for j in range(n):
                body += wrap(f"  COEF[{i}][{j}] = ", matrix[i * n + j])
            body += wrap(f"  RHS[{i}] = ", f"-({right[i]})")
        names = [self.plan.name_of(u) for u in self.unknowns]
        if solving.method == "linear":
            return (["/* Solve the linear equations for " + ", ".join(names) + " */"]
                    + body + [f"  if( solve({n}, COEF[0], RHS, SOL) )",
                              '    {printf("\\n The equations are singular for these '
                              'inputs\\n");  exit(1);}']
                    + [f"  {name} = SOL[{i}];" for i, name in enumerate(names)])
        # Newton's method from the guesses, as autolev run (docs/language.md)
        lines = ["/* Solve the nonlinear equations for " + ", ".join(names)
                 + " (Newton's method from the guesses) */",
                 "for(iter = 1; ; iter++)", "  {"]
        lines += ["  " + line for line in body]
        lines += [f"    if( solve({n}, COEF[0], RHS, SOL) )",
                  '      {printf("\\n The Jacobian is singular\\n");  exit(1);}',
                  "    converged = 1;"]
        for i, name in enumerate(names):
            lines += [f"    {name} += SOL[{i}];",
                      f"    if( !(fabs(SOL[{i}]) <= fmax(abserr, relerr*fabs({name}))) ) "
                      "converged = 0;"]
        lines += ["    if( converged ) break;",
                  f"    if( iter == {solving.ITERATIONS} )",
                  f'      {{printf("\\n Newton\'s method did not converge in '
                  f'{solving.ITERATIONS} iterations\\n");  exit(1);}}',
                  "  }"]
        return lines

    # -- sections ---------------------------------------------------------------------
    def _top(self) -> list[str]:
        p = self.plan
        lines = banner(self.name) + ["void     eqns1     (void);",
                                     "void     output    (FILE *Fptr[] );"]
        if self.unknowns:
            lines.append("int      solve     (int n, double *coef, double *rhs, "
                         "double *x);")
        lines += READING_PROTOTYPES
        # the inputs in read order; the others sorted by name ignoring case
        groups = (p.inputs, by_name(self.computed), by_name(p.specified), by_name(p.named))
        for group in groups:
            if group:
                lines += wrap("double   ", ",".join(p.name_of(s) for s in group))
        n = len(self.unknowns)
        solving = [f"COEF[{n}][{n}]", f"RHS[{n}]", f"SOL[{n}]"] if n else []
        if p.solving is not None and p.solving.method == "newton":
            solving += ["abserr", "relerr"]
        declared = {p.name_of(s) for group in groups for s in group}
        return lines + encoded_declarations(p.encoded, self.z_size, solving, declared) + [""]

    def _main(self) -> list[str]:
        p = self.plan
        infile = input_file_name(p.filename)
        lines = ["/* ................................ MAIN ............................. */",
                 "int      main         (void)", "{",
                 f"FILE     *Fptr[{self.nfiles + 1}];",
                 "int      iloop, ipoint;" if p.sweep else "int      iloop;", ""]
        lines += opening(infile, self.stem, self.nfiles)
        guesses = [s for s in p.inputs if s in self.unknowns]
        constants = [s for s in p.inputs if s not in guesses]
        for what, group in (("values of constants", constants),
                            ("the guess of each unknown", guesses)):
            if group:
                lines.append(f"/* Read {what} from input file */")
                lines += wrap("readf(Fptr[0],", ",".join("&" + p.name_of(s) for s in group),
                              ",NULL);")
        if guesses:
            lines += ["/* Read the tolerances of Newton's method from input file */",
                      "readf(Fptr[0],&abserr,&relerr,NULL);"]
        lines += [""] + headings_and_units(self.stem, p.files,
                                           [p.name_of(s) for s in p.degree_inputs])
        lines += ["", "/* Evaluate output quantities */"]
        sweep = p.sweep
        if sweep is None:
            lines += ["eqns1();", "output( Fptr );", ""]
        else:
            name = p.name_of(sweep.target) if sweep.target is not None else None
            lines += [f"for(ipoint = 0; ipoint < {sweep.count}; ipoint++)", "  {"]
            if name is not None:
                lines.append(f"  {name} = {sweep.start!r} + {sweep.step!r}*ipoint;")
                if sweep.degrees:
                    lines.append(f"  {name} = {name}*DEGtoRAD;")
            lines += ["  eqns1();", "  output( Fptr );", "  }", ""]
        return lines + farewell(infile, self.stem, self.nfiles)

    def _eqns1(self, computed: list) -> list[str]:
        lines = ["/* ................................ EQNS1 ............................. */",
                 "void     eqns1        (void)", "{"]
        if self.plan.solving is not None and self.plan.solving.method == "newton":
            lines.append("int      iter, converged;")
        lines += ["", "/* Evaluate constants */"]
        # quantities to be specified: 0, as in Autolev's programs
        lines += [f"  {self.plan.name_of(s)} = 0;" for s in self.plan.specified]
        return lines + computed + ["", "", "/* Evaluate output quantities */", "}"]

    def _output(self, written: list) -> list[str]:
        lines = ["/* ................................ OUTPUT ............................. */",
                 "void     output (FILE *Fptr[] )", "{"]
        if not self.plan.files:
            lines.append("(void)Fptr;                  /* no OUTPUT file to write */")
        lines += ["", "/* Write output to screen and to output file(s) */"] + written + [""]
        lines += [f"  Encode[{k}] = 0.0;" for k in range(len(self.plan.encoded))]
        return lines + ["", "}"]


def _lines(part, sources: dict) -> list[str]:
    return with_sources(part.statements, sources, c_comment,
                        lambda target, text: wrap(f"  {target} = ", text))


def c_comment(text: str) -> str:
    """A comment line of the model's own text (which cannot end the comment)."""
    safe = "".join(ch if " " <= ch <= "~" else "?" for ch in text).replace("*/", "* /")
    return f"/* {safe} */"


# -- pieces every C program has --------------------------------------------------------
def banner(name: str) -> list[str]:
    """The program's first lines: its name, who made it, the headers, _NAN."""
    return [f"/* The name of this program is {name} */",
            f"/* Created by autolev {__version__} in the layout of Autolev 4.1's "
            "programs */", "",
            "#include <ctype.h>", "#include <math.h>", "#include <stdarg.h>",
            "#include <stdio.h>", "#include <stdlib.h>", "#include <string.h>",
            "#define  _NAN      9.99999999999999E+305", ""]


READING_PROTOTYPES = ["void     readf     (FILE *Fp, double *next, ...);",
                      "void     pgets     (FILE *Fp, double *x);",
                      "void     writef    (FILE *Fp, char format[], ...);", ""]


def opening(infile: str, stem: str, nfiles: int) -> list[str]:
    """main's opening of NAME.in and NAME.1 ... NAME.nfiles, and of the .in file's six
    heading lines."""
    return ["/* Open input and output files */",
            f"for(iloop = 0; iloop <= {nfiles}; iloop++)", "  {",
            "  char fileName[256];",
            f'  if( iloop == 0 ) strcpy(fileName, "{c_string(infile)}");',
            f'  else sprintf(fileName, "{c_string(stem, fmt=True)}.%d", iloop);',
            '  Fptr[iloop] = fopen(fileName, iloop ? "w" : "r");',
            "  if( Fptr[iloop] == NULL )",
            '    {printf("Error: unable to open file %s\\n", fileName);  exit(0);}',
            "  }", "",
            "/* Read top of input file */",
            "for(iloop = 0; iloop < 6; iloop++) pgets(Fptr[0], NULL);", ""]


def headings_and_units(stem: str, files: list, degree_inputs: list) -> list[str]:
    """The headings of the output files (file 1's also on the screen), then the unit
    conversions of the inputs (`degree_inputs`: their names in the program)."""
    lines = ["/* Write heading(s) to output file(s) */"]
    for k, cols in enumerate(files, 1):
        head = output_header(f"{stem}.{k}", [c[1] for c in cols], [c[2] for c in cols])
        for target in (["stdout", f"Fptr[{k}]"] if k == 1 else [f"Fptr[{k}]"]):
            lines.append(f'fprintf({target}, "{c_string(head, fmt=True)}");')
    lines += ["", "/* Unit conversions */", "  Pi       = 3.141592653589793;",
              "  DEGtoRAD = Pi/180.0;", "  RADtoDEG = 180.0/Pi;"]
    return lines + [f"  {n} = {n}*DEGtoRAD;" for n in degree_inputs]


def farewell(infile: str, stem: str, nfiles: int) -> list[str]:
    """main's last lines: where the input and output are, the files closed."""
    lines = ["/* Inform user of input and output filename(s) */",
             f'puts( "\\n Input is in the file {c_string(infile)}" );']
    if nfiles:
        what = (f"file {stem}.1" if nfiles == 1 else f"files {stem}.i  (i=1,...,{nfiles})")
        lines.append(f'puts( "\\n Output is in the {c_string(what)}" );')
    lines += [f"fclose(Fptr[{k}]);" for k in range(nfiles + 1)]
    return lines + ["return 0;", "}"]


def output_lines(files: list, encoded: list, texts: list) -> list[str]:
    """output()'s lines from the printed texts of shown_values: a writef per OUTPUT
    file (file 1 also to the screen; DEG columns converted), then the ENCODE elements
    (an exact zero written `= 0;`, as BioMAC's cleaners count them)."""
    texts = list(texts)
    lines = []
    for k, cols in enumerate(files, 1):
        row = []
        for _, _, unit in cols:
            text = texts.pop(0)
            text = "0.0" if text == "0" else text      # writef reads doubles
            row.append(f"({text})*RADtoDEG" if units.is_degrees(unit) else text)
        for target in (["stdout", f"Fptr[{k}]"] if k == 1 else [f"Fptr[{k}]"]):
            lines += wrap(f'  writef({target}, " %- 14.6E", ', ",".join(row), ",_NAN);")
    for e in encoded:
        for index in element_indices(e.shape):
            text = texts.pop(0)
            target = e.name + "".join(f"[{i}]" for i in index)
            if text == target:
                continue            # a quantity the program computes by that name already
            lines += [f"  {target} = 0;"] if text == "0" else wrap(f"  {target} = ", text)
    return lines


def encoded_declarations(encoded: list, z_size: int, extra=(), declared=()) -> list[str]:
    """The line of z, the ENCODE arrays and Encode (BioMAC's cleaners read z's size
    from its first 32 characters); `declared`: names the program declares already (a
    named quantity ENCODE'd as it is)."""
    arrays = [f"z[{z_size + 1}]"] + [e.name + "".join(f"[{d}]" for d in e.shape)
                                     for e in encoded if e.shape or e.name not in declared]
    arrays += [f"Encode[{max(1, len(encoded))}]", *extra]
    return wrap("double   Pi,DEGtoRAD,RADtoDEG,", ",".join(arrays))


def by_name(symbols: list) -> list:
    return sorted(symbols, key=lambda s: (c_name(s).lower(), c_name(s)))


# the functions every program carries: Autolev's names and behaviour (the value of a
# line of the .in file starts in its 60th character), written for autolev
READING_AND_WRITING = r"""
/*................................... READF ................................*/
void  readf( FILE *Fp, double *next, ... )
{
va_list  args;
va_start(args, next);
while( next != NULL )
  {
  pgets(Fp, next);
  next = va_arg(args, double *);
  }
va_end(args);
pgets(Fp, NULL);                       /* the line that closes the group of values */
}


/*................................... PGETS ................................*/
void  pgets( FILE *Fp, double *x )
{
static long  lineNumber = 0;
char         line[256];
char         *end;

lineNumber++;
if( fgets(line, sizeof line, Fp) == NULL )
  {
  printf("\n The input file ends before line %ld.\n", lineNumber);
  exit(0);
  }
if( x == NULL ) return;
if( strlen(line) >= 60 )
  {
  *x = strtod(line + 59, &end);
  while( isspace((unsigned char)*end) ) end++;
  if( *end == '\0' ) return;
  }
printf("\n Line %ld of the input file should hold one number, starting in its"
       "\n 60th character:\n\n%s\n", lineNumber, line);
exit(0);
}


/* .................................. WRITEF .............................. */
void  writef( FILE *Fp, char format[], ... )
{
va_list  args;
double   value;
va_start(args, format);
for( value = va_arg(args, double);  value != _NAN;  value = va_arg(args, double) )
  fprintf(Fp, format, value);
va_end(args);
fprintf(Fp, "\n");
}""".splitlines()[1:]


# coef x = rhs, for the mass matrix of a DYNAMICS program and the equations of an
# ALGEBRAIC or NONLINEAR one, written for autolev
SOLVE = r"""
/* ................................ SOLVE ............................. */
/* coef x = rhs (n by n, row by row) by Gaussian elimination with partial pivoting
 * (each pivot inverted once); 1 when a pivot is exactly zero.  coef and rhs are
 * overwritten. */
int      solve (int n, double *coef, double *rhs, double *x)
{
int      i, j, k, p;
for( k = 0; k < n; k++ )
  {
  double big = fabs(coef[k * n + k]), r;
  p = k;
  for( i = k + 1; i < n; i++ )
    if( fabs(coef[i * n + k]) > big ) { big = fabs(coef[i * n + k]);  p = i; }
  if( big == 0.0 ) return 1;
  if( p != k )
    {
    for( j = 0; j < n; j++ )
      { double s = coef[k * n + j];  coef[k * n + j] = coef[p * n + j];  coef[p * n + j] = s; }
    { double s = rhs[k];  rhs[k] = rhs[p];  rhs[p] = s; }
    }
  r = 1.0 / coef[k * n + k];
  x[k] = r;
  for( i = k + 1; i < n; i++ )
    {
    double l = coef[i * n + k] * r;
    if( l != 0.0 )
      {
      for( j = k + 1; j < n; j++ ) coef[i * n + j] -= l * coef[k * n + j];
      rhs[i] -= l * rhs[k];
      }
    }
  }
for( i = n - 1; i >= 0; i-- )
  {
  double acc = rhs[i], r = x[i];
  for( j = i + 1; j < n; j++ ) acc -= coef[i * n + j] * x[j];
  x[i] = acc * r;
  }
return 0;
}""".splitlines()[1:]


def write_c(plan: Plan) -> dict:
    """{file name: text}: the program and the .in file it reads."""
    return {plan.filename: CProgram(plan).text(),
            input_file_name(plan.filename): plan.input_text}


__all__ = ["write_c", "wrap", "c_string"]
