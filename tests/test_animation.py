"""The motion of a model as a picture (issue 19, item 6): positions from the model's
own points, a page that shows them (tested in a real headless browser where one is
installed), a GIF."""
import math
import shutil
import subprocess

import numpy as np
import pytest

import autolev
from autolev import animation
from autolev.runtime import AutolevModelError
from helpers import EXAMPLES


@pytest.fixture(scope="module")
def pendulum_run():
    model = autolev.load(EXAMPLES / "double_pendulum.al")
    return model, model.simulate(TFINAL=2)


def test_the_figure_is_the_models_points_where_they_are(pendulum_run):
    model, result = pendulum_run
    m = animation.motion(model, result, max_frames=50)
    assert m.names == ["NO", "P1", "P2"] and m.edges == [(0, 1), (1, 2)] and m.planar
    assert len(m.times) == 50 and m.times[0] == 0 and m.times[-1] == result.t[-1]
    # by hand: P1 = L1 (cos Q1, sin Q1), P2 = P1 + L2 (cos Q2, sin Q2), L1 = L2 = 1
    k = list(result.t).index(m.times[17])
    q1, q2 = result["Q1"][k], result["Q2"][k]
    p1 = [math.cos(q1), math.sin(q1), 0]
    p2 = [p1[0] + math.cos(q2), p1[1] + math.sin(q2), 0]
    assert np.allclose(m.xyz[17], [[0, 0, 0], p1, p2], atol=1e-12)


def test_a_length_only_the_figure_uses_comes_from_input(tmp_path):
    # the link length D enters no equation: the run has no value for it
    path = tmp_path / "arm.al"
    path.write_text("NEWTONIAN N\nFRAMES A\nPOINTS P, Q\nVARIABLES TH'\nCONSTANTS D, E\n"
                    "SIMPROT(N, A, 3, TH)\nTH' = 1\nP_NO_P> = D*A1>\nP_P_Q> = E*A2>\n"
                    "INPUT TH = 0, D = 2\nOUTPUT T, TH\nCODE ODE() arm.c\n")
    model = autolev.load(path)
    result = model.simulate(TFINAL=1)
    with pytest.raises(AutolevModelError, match="the figure needs values the run does "
                       "not: E"):
        animation.motion(model, result)
    path.write_text(path.read_text().replace("D = 2", "D = 2, E = 0.5"))
    model = autolev.load(path)
    m = animation.motion(model, model.simulate(TFINAL=1))
    th = m.times[-1]                                   # TH = T
    assert np.allclose(m.xyz[-1, 1], [2 * math.cos(th), 2 * math.sin(th), 0])
    assert np.allclose(m.xyz[-1, 2], m.xyz[-1, 1] + 0.5 * np.array(
        [-math.sin(th), math.cos(th), 0]))


def test_a_model_with_nothing_located_says_so(tmp_path):
    path = tmp_path / "free.al"
    path.write_text("NEWTONIAN N\nVARIABLES X'\nX' = 1\nOUTPUT T, X\nCODE ODE() f.c\n")
    model = autolev.load(path)
    with pytest.raises(AutolevModelError, match="no point has a position from NO"):
        animation.motion(model, model.simulate(TFINAL=0.2))


def hostile_motion():
    return animation.Motion("N", ["NO", "</script><script>alert(1)</script>"], [(0, 1)],
                            [], np.array([0.0, 1.0]),
                            np.array([[[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [0, 1, 0]]]))


def test_names_and_titles_from_outside_never_become_markup(tmp_path):
    page = animation.write_html(hostile_motion(), tmp_path / "m.html",
                                'x"><script>alert(2)</script>').read_text()
    assert page.count("<script") == 2 and page.count("</script>") == 2
    assert "<title>x&quot;&gt;&lt;script&gt;alert(2)&lt;/script&gt;</title>" in page
    assert "\\u003c/script\\u003e" in page


def test_the_gif_has_a_frame_per_drawn_row(pendulum_run, tmp_path):
    pytest.importorskip("matplotlib", reason="a GIF needs the optional matplotlib")
    from PIL import Image
    model, result = pendulum_run
    m = animation.motion(model, result, max_frames=30)
    gif = animation.write_movie(m, tmp_path / "p.gif")
    with Image.open(gif) as im:
        assert im.n_frames == 30


def chromium():
    return shutil.which("chromium") or shutil.which("chromium-browser")


def screenshot(page, png, time_budget_ms=200):
    subprocess.run([chromium(), "--headless", "--no-sandbox", "--disable-gpu",
                    "--hide-scrollbars", "--window-size=800,600",
                    f"--virtual-time-budget={time_budget_ms}", f"--screenshot={png}",
                    page.as_uri()], check=True, capture_output=True, timeout=120)


def colour_count(png, rgb, tolerance=30) -> int:
    from PIL import Image
    with Image.open(png) as im:
        a = np.asarray(im.convert("RGB"), dtype=int)
    return int((np.abs(a - np.array(rgb)).max(axis=2) <= tolerance).sum())


@pytest.mark.browser
@pytest.mark.skipif(chromium() is None, reason="needs a headless Chromium (Debian: chromium)")
def test_the_page_shows_the_figure_in_a_real_browser(pendulum_run, tmp_path):
    pytest.importorskip("PIL", reason="reading the screenshot needs Pillow")
    model, result = pendulum_run
    page = animation.write_html(animation.motion(model, result), tmp_path / "p.html",
                                "double pendulum")
    png = tmp_path / "shot.png"
    screenshot(page, png)
    links = colour_count(png, (0x1f, 0x77, 0xb4))        # the links' blue
    dots = colour_count(png, (0xff, 0x7f, 0x0e))         # the points' orange
    # two links of 1 m in a 2 m by 2 m box on a 560-pixel canvas: hundreds of pixels
    assert links > 600 and dots > 60, (links, dots)
    # a page with no figure in it draws none of them
    empty = animation.Motion("N", ["NO"], [], [], np.array([0.0]), np.zeros((1, 1, 3)))
    bare = animation.write_html(empty, tmp_path / "bare.html", "nothing")
    screenshot(bare, tmp_path / "bare.png")
    assert colour_count(tmp_path / "bare.png", (0x1f, 0x77, 0xb4)) == 0


def test_autolev_animate_writes_the_run_and_its_motion(tmp_path):
    from autolev.cli import main
    code = main(["animate", str(EXAMPLES / "double_pendulum.al"), "--out", str(tmp_path),
                 "--tfinal", "0.5", "--format", "html", "-q"])
    assert code == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "double_pendulum.1", "double_pendulum.2", "double_pendulum.dir",
        "double_pendulum.html", "double_pendulum.in"]
    page = (tmp_path / "double_pendulum.html").read_text()
    assert '"names":["NO","P1","P2"]' in page and '"times":[0.0,' in page
