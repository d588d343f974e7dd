"""`autolev transcript` and `autolev verify`: the responses Autolev displayed,
written and replayed.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import (AutolevRuntimeError, AutolevSyntaxError, AutolevTranslationError,
                      printable_lines)
from .common import UsageError, failure_diagnostics, overwrite_option, print_diagnostics


def cmd_transcript(ns: argparse.Namespace) -> int:
    """The responses Autolev displayed for each statement, as its .all files."""
    return print_transcript(Path(ns.file), Path(ns.out) if ns.out else None, ns.overwrite)


def print_transcript(path: Path, out_dir: Path | None, overwrite: bool = False) -> int:
    if path.suffix.lower() == ".py":
        raise UsageError(f"{path}: a transcript is made from the .al model")
    text = transcript_text(path)
    if text is None:
        return 1
    if out_dir is None:
        sys.stdout.write(printable_lines(text))     # a model's comments hold escapes too
        return 0
    from ..engine.outputs import write_output
    target = out_dir / f"{path.stem}.all"
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
        write_output(out_dir, target.name, text, overwrite)
    except OSError as exc:
        print(f"autolev transcript: cannot write {target}: {exc.strerror}", file=sys.stderr)
        return 1
    print(f"wrote {target}")
    model_folder = path.resolve().parent
    if out_dir.resolve() != model_folder and any(
            f.suffix.lower() == ".r" for f in model_folder.iterdir()):
        # the transcript shows a user function's call as it was typed, as Autolev did
        print(f"  verify it with: autolev verify {target} --model-folder {path.parent}"
              " (its user functions' .R files are there)")
    return 0


def transcript_text(path: Path) -> str | None:
    """The transcript of the .al model at `path` (kept for the files it read, as read,
    and read back while each is unchanged); None after printing the diagnostics of a
    model it cannot be made for."""
    from ..engine.request import TranscriptRequest
    from ..engine.keeping import keep, kept
    from ..engine.transcripts import KeptTranscript
    from ..engine import reading
    request = TranscriptRequest.of_file(path)
    with reading.recording() as reads:
        found = kept(request, reads, lambda: KeptTranscript)
        if found is not None:
            return found.text
        from ..transcript import transcript
        try:
            text = transcript(path)
        except (AutolevSyntaxError, AutolevTranslationError, AutolevRuntimeError) as exc:
            print_diagnostics(failure_diagnostics(path, exc))
            return None
        keep(request, reads, lambda read: KeptTranscript(read, text))
    return text


def cmd_verify(ns: argparse.Namespace) -> int:
    """Replay Autolev's recorded responses; exit 0 only when every comparable one matches."""
    import json

    from autolev.verification import verify

    path = Path(ns.file)
    if not path.exists():
        raise UsageError(f"{path}: no such file")
    folder = Path(ns.model_folder) if ns.model_folder else None
    if folder is not None and not folder.is_dir():
        raise UsageError(f"--model-folder {folder}: no such folder")
    report = verify(path, points=ns.points, folder=folder, progress=sys.stderr)
    if ns.json:
        print(json.dumps(report.as_dict(), indent=1))
    else:
        if report.error:
            print(printable_lines(f"{path}: {report.error}"), file=sys.stderr)
        for o in report.outcomes:
            if o.status == "match" and not ns.all:
                continue
            r = o.response
            line = printable_lines(f"{path}:{r.line}: ({r.number}) {r.lhs}: {o.status}: "
                                   f"{o.detail}")
            if o.status == "mismatch" and o.ours is not None:
                line += f"\n    ours {_short(o.ours)}\n    Autolev's {_short(o.theirs)}"
            print(line)
        print(report.summary())
    return 0 if report.ok else 1


def _short(v) -> str:
    import numpy as np
    a = np.asarray(v, dtype=complex)
    a = a.real if np.all(np.abs(a.imag) < 1e-12) else a
    return np.array2string(a, precision=8, max_line_width=100)


def add_transcript(sub) -> None:
    tr = sub.add_parser("transcript", help="the responses Autolev displayed (.all)",
                        description="Print what Autolev displayed for FILE: every input "
                        "line numbered (n), and after each assignment the value it defined "
                        "(with the Z variables it uses), as in Autolev's .all files.  "
                        "`autolev verify NAME.all` replays such a transcript.")
    tr.add_argument("file", metavar="FILE", help=".al model")
    tr.add_argument("--out", metavar="DIR", help="write DIR/NAME.all instead of printing")
    overwrite_option(tr)
    tr.set_defaults(func=cmd_transcript)


def add_verify(sub) -> None:
    ver = sub.add_parser("verify", help="check a translation against Autolev's responses",
                         description="Replay the responses Autolev printed (an .all session "
                         "saved by SAVE, or a .al file with '% ->' response comments): each "
                         "is compared with our translation's value at the same point of the "
                         "model, numerically at several values of every name, to the digits "
                         "Autolev displayed.  Exit status 0 only when every comparable "
                         "response matches.")
    ver.add_argument("file", metavar="FILE", help=".all session or .al file")
    ver.add_argument("--json", action="store_true", help="machine-readable report")
    ver.add_argument("--all", action="store_true", help="list the matches too")
    ver.add_argument("--points", type=int, default=3, metavar="N",
                     help="sample points per response (default 3)")
    ver.add_argument("--model-folder", metavar="DIR",
                     help="the model's folder, where its macro (.a), function (.R) and RUN "
                     "files are, for a session kept elsewhere (a transcript written with "
                     "--out); looked in after the session's own folder")
    ver.set_defaults(func=cmd_verify)
