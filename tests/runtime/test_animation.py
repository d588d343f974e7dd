"""The motion of a model as a picture (issue 19, item 6; issue 29, item 3): the skeleton
of the model's positions, a page that shows them (tested in a real headless browser where
one is installed, its script under Node.js), a GIF."""
import math
import shutil
import subprocess
import warnings

import numpy as np
import pytest

import autolev
from autolev.cli import main as cli_main
from autolev.runtime import animation, animation_output
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
    # E given nowhere: P_P_Q> is left out, the arm NO-P is drawn
    m = animation.motion(model, result)
    assert m.names == ["NO", "P"] and m.edges == [(0, 1)]
    assert m.notes == ["E has no value (neither INPUT nor --set gives it and the run does "
                       "not need it): P_P_Q> not drawn"]
    th = m.times[-1]
    assert np.allclose(m.xyz[-1, 1], [2 * math.cos(th), 2 * math.sin(th), 0])
    path.write_text(path.read_text().replace("D = 2", "D = 2, E = 0.5"))
    model = autolev.load(path)
    m = animation.motion(model, model.simulate(TFINAL=1))
    th = m.times[-1]                                   # TH = T
    assert np.allclose(m.xyz[-1, 1], [2 * math.cos(th), 2 * math.sin(th), 0])
    assert np.allclose(m.xyz[-1, 2], m.xyz[-1, 1] + 0.5 * np.array(
        [-math.sin(th), math.cos(th), 0]))


def test_a_length_only_the_figure_uses_comes_from_set(tmp_path, capsys):
    # --set E=0.5 reached the run only ("not an input ... ignored there"): the figure
    # left P_P_Q> out for want of E, though the user gave it
    path = tmp_path / "arm.al"
    path.write_text("NEWTONIAN N\nFRAMES A\nPOINTS P, Q\nVARIABLES TH'\nCONSTANTS D, E\n"
                    "SIMPROT(N, A, 3, TH)\nTH' = 1\nP_NO_P> = D*A1>\nP_P_Q> = E*A2>\n"
                    "INPUT TH = 0, D = 2, TFINAL = 1\nOUTPUT T, TH\nCODE ODE() arm.c\n")
    model = autolev.load(path)
    result = model.simulate(keep_rows=True)
    m = animation.motion(model, result, overrides={"e": "0.5", "D": 3})
    assert m.names == ["NO", "P", "Q"] and not m.notes
    th = m.times[-1]
    # INPUT D = 2 is the run's (D enters no equation either: the figure takes --set's 3)
    assert np.allclose(m.xyz[-1, 1], [3 * math.cos(th), 3 * math.sin(th), 0])
    assert np.allclose(m.xyz[-1, 2] - m.xyz[-1, 1], [-0.5 * math.sin(th),
                                                     0.5 * math.cos(th), 0])
    out = tmp_path / "out"
    assert cli_main(["animate", str(path), "--out", str(out), "--format", "html",
                             "--set", "E=0.5"]) == 0
    assert "P_P_Q> not drawn" not in capsys.readouterr().err
    assert '"Q"' in (out / "arm.html").read_text()


def test_a_model_with_nothing_located_says_so(tmp_path):
    path = tmp_path / "free.al"
    path.write_text("NEWTONIAN N\nVARIABLES X'\nX' = 1\nOUTPUT T, X\nCODE ODE() f.c\n")
    model = autolev.load(path)
    with pytest.raises(AutolevModelError, match="there is no figure to draw: no positions "
                       "link the points"):
        animation.motion(model, model.simulate(TFINAL=0.2))


def hostile_motion():
    return animation.Motion("N", ["NO", "</script><script>alert(1)</script>"], [(0, 1)],
                            [], np.array([0.0, 1.0]),
                            np.array([[[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [0, 1, 0]]]))


def test_names_and_titles_from_outside_never_become_markup(tmp_path):
    page = animation_output.write_html(hostile_motion(), tmp_path / "m.html",
                                'x"><script>alert(2)</script>').read_text()
    assert page.count("<script") == 2 and page.count("</script>") == 2
    assert "<title>x&quot;&gt;&lt;script&gt;alert(2)&lt;/script&gt;</title>" in page
    assert "\\u003c/script\\u003e" in page


def test_the_gif_has_a_frame_per_drawn_row(pendulum_run, tmp_path):
    pytest.importorskip("matplotlib", reason="a GIF needs the optional matplotlib")
    from PIL import Image
    model, result = pendulum_run
    m = animation.motion(model, result, max_frames=30)
    gif = animation_output.write_movie(m, tmp_path / "p.gif")
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
    page = animation_output.write_html(animation.motion(model, result), tmp_path / "p.html",
                                "double pendulum")
    png = tmp_path / "shot.png"
    screenshot(page, png)
    links = colour_count(png, (0x1f, 0x77, 0xb4))        # the links' blue
    joints = colour_count(png, (0xff, 0x7f, 0x0e))       # a joint's orange (NO)
    masses = colour_count(png, (0xd6, 0x27, 0x28))       # the particles' red, larger
    # two links of 1 m in a 2 m by 2 m box on a 560-pixel canvas: hundreds of pixels
    assert links > 600 and joints > 20 and masses > 2 * joints, (links, joints, masses)
    # a page with no figure in it draws none of them
    empty = animation.Motion("N", ["NO"], [], [], np.array([0.0]), np.zeros((1, 1, 3)))
    bare = animation_output.write_html(empty, tmp_path / "bare.html", "nothing")
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


# -- the skeleton a person would draw (issue 29, item 3) -------------------------------------
# A leg hung from O, fixed in N, by a translation of the hip (as gait and sprint models
# do): hip (X, H), knee L1 along -A2>, ankle L2 along -B2>; X = T, TH = T, PH = T/2.
WALKER = """NEWTONIAN N
FRAMES A, B
POINTS O, HIP, KNEE, ANKLE
VARIABLES X', TH', PH'
CONSTANTS H, L1, L2, G
SIMPROT(N, A, 3, TH)
SIMPROT(A, {knee_axis}, PH)
X' = {speed}
TH' = 1
PH' = 0.5
V_O_N> = 0>
{before}
P_O_HIP> = X*N1> + H*N2>
P_HIP_KNEE> = -L1*A2>
P_KNEE_ANKLE> = -L2*B2>
{after}
INPUT H = 1, L1 = 0.5, L2 = 0.4, G = 9.81, X = {x0}, TFINAL = 1
OUTPUT T, X
CODE ODE() walker.c
"""


def walker(tmp_path, before="", after="", knee_axis="B, 3", x0=0, speed=1):
    path = tmp_path / "walker.al"
    path.write_text(WALKER.format(before=before, after=after, knee_axis=knee_axis, x0=x0,
                                  speed=speed))
    model = autolev.load(path)
    return animation.motion(model, model.simulate(), max_frames=11)


def leg_by_hand(t, x0=0.0):
    th, ph = t, t / 2
    hip = np.array([x0 + t, 1.0, 0.0])
    knee = hip + 0.5 * np.array([math.sin(th), -math.cos(th), 0])
    ankle = knee + 0.4 * np.array([math.sin(th + ph), -math.cos(th + ph), 0])
    return np.array([hip, knee, ankle])


FANS = {
    "the chain alone": ("", ""),
    # every point positioned from O as well, written out before the chain ...
    "a fan written out first": ("P_O_KNEE> = X*N1> + H*N2> - L1*A2>\n"
                                "P_O_ANKLE> = X*N1> + H*N2> - L1*A2> - L2*B2>", ""),
    # ... or built from it afterwards, one of them expressed in N
    "a fan built from the chain": ("", "P_O_KNEE> = P_O_HIP> + P_HIP_KNEE>\n"
                                   "P_O_ANKLE> = EXPRESS(P_O_KNEE> + P_KNEE_ANKLE>, N)"),
    # O put at NO (the way round "no point has a position from NO"): a link of
    # no length, drawn as nothing
    "O at NO": ("P_NO_O> = 0>", "P_O_KNEE> = P_O_HIP> + P_HIP_KNEE>"),
}


@pytest.mark.parametrize("fan", FANS)
def test_the_figure_is_the_chain_not_the_fan_from_the_fixed_point(tmp_path, fan):
    m = walker(tmp_path, *FANS[fan])
    # O only places the hip (a translation in N): not drawn, and no line from it
    assert m.names == ["HIP", "KNEE", "ANKLE"] and m.edges == [(0, 1), (1, 2)]
    assert m.notes == [] and m.kinds == [animation.SEGMENT] * 2
    for k in (0, 5, 10):
        assert np.allclose(m.xyz[k], leg_by_hand(m.times[k]), atol=1e-12)


def test_a_figure_standing_still_is_placed_as_one_that_moves(tmp_path):
    # the hip's translation keeps its length over this run but not at the probe state
    m = walker(tmp_path, speed=0)
    assert m.names == ["HIP", "KNEE", "ANKLE"] and m.edges == [(0, 1), (1, 2)]


def test_a_link_that_closes_a_loop_is_drawn(tmp_path):
    # a parallelogram: P_R_Q> is the sum along R, NO, P, Q at every state but is no more
    # than one side (as local as the others): a loop, kept; so is a loop that does not close
    text = ("NEWTONIAN N\nFRAMES A, B\nPOINTS P, Q, R\nVARIABLES TH'\nCONSTANTS C, W\n"
            "SIMPROT(N, A, 3, TH)\nSIMPROT(N, B, 3, 2*TH)\nTH' = 1\n"
            "P_NO_P> = C*A1>\nP_P_Q> = W*N1>\nP_NO_R> = W*N1>\nP_R_Q> = C*{}1>\n"
            "INPUT C = 1, W = 2, TH = 0.3, TFINAL = 1\nOUTPUT T, TH\nCODE ODE() bars.c\n")
    for frame in "AB":
        path = tmp_path / f"bars{frame}.al"
        path.write_text(text.format(frame))
        model = autolev.load(path)
        m = animation.motion(model, model.simulate(), max_frames=5)
        sides = {frozenset((m.names[a], m.names[b])) for a, b in m.edges}
        assert sides == {frozenset(s) for s in (("NO", "P"), ("P", "Q"), ("NO", "R"),
                                                 ("R", "Q"))}, frame
        th = m.times[-1] + 0.3
        assert np.allclose(m.xyz[-1, m.names.index("Q")],
                           [math.cos(th) + 2, math.sin(th), 0], atol=1e-12)


@pytest.mark.parametrize("gravity, basis", [
    # down along +N2: up is -N2, N3 still toward the viewer, so -N1 is to the right
    ("GRAVITY(G*N2>)", [[-1, 0, 0], [0, -1, 0], [0, 0, 1]]),
    ("GRAVITY(-G*N2>)", [[1, 0, 0], [0, 1, 0], [0, 0, 1]]),
    ("GRAVITY(G*N1>)", [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]),
    ("", [[1, 0, 0], [0, 1, 0], [0, 0, 1]]),            # no gravity: N1 right, N2 up
])
def test_up_is_opposite_to_gravity(tmp_path, gravity, basis):
    m = walker(tmp_path, after=gravity)
    assert np.allclose(m.basis, basis, atol=1e-12) and m.planar
    hip = leg_by_hand(m.times[-1])[0]
    assert np.allclose(m.picture[-1, 0], np.array(basis) @ hip, atol=1e-12)


def test_a_motion_out_of_a_plane_is_seen_from_the_side_with_gravity_down(tmp_path):
    # the knee turns about A1>: the ankle leaves the plane; down along +N3 makes up -N3,
    # the depth the most level axis (N2 before N1) and the right (-N3) x N2 = N1
    m = walker(tmp_path, after="GRAVITY(G*N3>)", knee_axis="B, 1")
    assert not m.planar
    assert np.allclose(m.basis, [[1, 0, 0], [0, 0, -1], [0, 1, 0]], atol=1e-12)


def test_the_view_is_framed_on_the_motion_not_on_the_origin(tmp_path):
    m = walker(tmp_path, x0=6)                # the leg 6 m from O, which is not drawn
    lo, hi = m.view_box()
    points = m.picture.reshape(-1, 3)
    assert np.all(lo <= points.min(axis=0)) and np.all(points.max(axis=0) <= hi)
    # by hand: the hip goes from x = 6 to 7; the ankle's lowest x is 6 + 0, its highest
    # y 1 - 0.5 cos(1) - 0.4 cos(1.5) at T = 1 ... the box is the points' plus 5 %
    extent = points.max(axis=0) - points.min(axis=0)
    pad = animation.MARGIN * extent.max()
    assert np.allclose(lo, points.min(axis=0) - pad) and np.allclose(hi, points.max(axis=0) + pad)
    assert lo[0] > 5.9 and lo[0] == pytest.approx(6 - pad)


def test_the_view_follows_a_figure_that_travels_far_over_a_grid_fixed_in_n(tmp_path):
    still = walker(tmp_path)                     # 1 m of travel for a leg 0.9 m long
    assert not still.follows and still.grid() is None
    centres, width = still.view()
    lo, hi = still.view_box()
    assert np.allclose(centres, (lo + hi) / 2) and width == pytest.approx((hi - lo).max())
    m = walker(tmp_path, speed=10)               # 10 m: more than 3 times its size
    assert m.follows
    centres, width = m.view()
    p = m.picture
    assert np.allclose(centres, p.mean(axis=1))  # each frame about its own points
    reach = np.linalg.norm(p - centres[:, None], axis=2).max()
    assert width == pytest.approx(2 * reach * (1 + 2 * animation.MARGIN))
    # a quarter of the view is about 0.26 m: the nearest of 0.1, 0.2, 0.5 ... is 0.2
    assert width / 4 == pytest.approx(0.26, abs=0.03)
    assert m.grid() == {"step": 0.2, "axes": [0, 1], "level": 0.0}
    lines = animation.grid_lines(m.grid(), centres[5], width)
    across = sorted(ends[0, 0] for ends, _ in lines if ends[0, 0] == ends[1, 0])
    # every 0.2 m across the view and a width either side of its centre
    assert np.allclose(np.diff(across), 0.2)
    assert across[0] - 0.2 < centres[5][0] - width <= across[0]
    assert across[-1] <= centres[5][0] + width < across[-1] + 0.2
    assert [major for ends, major in lines if ends[0, 0] == ends[1, 0]] == [
        round(x / 0.2) % 5 == 0 for x in across]


def test_labels_go_to_joints_first_and_never_cover_each_other(tmp_path):
    m = walker(tmp_path)
    assert [m.names[k] for k in m.labelled] == ["KNEE", "HIP", "ANKLE"]
    model = autolev.load(EXAMPLES / "nlink_pendulum.al")
    m = animation.motion(model, model.simulate(TFINAL=0.1), max_frames=2)
    labelled = {m.names[k] for k in m.labelled}
    assert labelled == {"NO", "P1", "P2", "P3"}       # mass centres AO ... DO are not
    assert {m.names[k] for k in m.centers} == {"AO", "BO", "CO", "DO"}
    # a label is left out where it would cover one placed before it
    boxes = [(0, 0, 10, 5), (8, 3, 18, 8), (11, 0, 20, 5), (0, 6, 5, 9)]
    assert animation_output.shown_labels(boxes) == [True, False, True, True]


SPIN = """NEWTONIAN N
BODIES A, B
VARIABLES TH', PH'
SIMPROT(N, A, 3, TH)
SIMPROT(A, B, 1, PH)
TH' = 1
PH' = 2
INPUT TFINAL = 1
OUTPUT T, TH
CODE ODE() spin.c
"""


def test_a_body_with_no_positioned_points_shows_its_axes_turning(tmp_path):
    path = tmp_path / "spin.al"
    path.write_text(SPIN)
    model = autolev.load(path)
    m = animation.motion(model, model.simulate(), max_frames=11)
    assert m.names == ["A", "A1>", "A2>", "A3>", "B", "B1>", "B2>", "B3>"]
    assert m.edges == [(0, 1), (0, 2), (0, 3), (4, 5), (4, 6), (4, 7)]
    assert m.kinds == [1, 2, 3, 1, 2, 3] and m.labelled == [1, 2, 3, 5, 6, 7]
    assert np.allclose(m.basis, np.eye(3))
    t = m.times[-1]
    th, ph = t, 2 * t
    a1 = np.array([math.cos(th), math.sin(th), 0])
    a2 = np.array([-math.sin(th), math.cos(th), 0])
    a3 = np.array([0, 0, 1])
    b = [a1, math.cos(ph) * a2 + math.sin(ph) * a3, -math.sin(ph) * a2 + math.cos(ph) * a3]
    beside = np.array([animation.TRIAD_SPACING, 0, 0])   # B's triad to the right of A's
    assert np.allclose(m.xyz[-1], [[0, 0, 0], a1, a2, a3, beside] + [beside + v for v in b],
                       atol=1e-12)
    # a body at a point it is positioned at with 0> is drawn by its axes too
    model = autolev.load(EXAMPLES / "euler_parameters_body.al")
    m = animation.motion(model, model.simulate(TFINAL=0.1), max_frames=2)
    assert m.names == ["B", "B1>", "B2>", "B3>"] and m.kinds == [1, 2, 3]


@pytest.mark.parametrize("rate, final", [
    # a constant rate about A's axis (1, 0, 2)/sqrt(5): turned by that rate times T
    ("W_A_N> = U*A1> + 2*U*A3>\nU' = 0\nINPUT U = 1.5", lambda t: [1.5 * t, 0, 3 * t]),
    # about A3 at the rate T^2: turned by T^3/3 about N3
    ("W_A_N> = U*A3>\nU' = 2*T\nINPUT U = 0", lambda t: [0, 0, t ** 3 / 3])])
def test_a_body_known_by_its_angular_velocity_alone_turns_with_it(rate, final, tmp_path):
    """No orientation, only W_A_N> in A's axes (Kane's gyrostat, example 5.9): the axes
    start along N's and turn with the rate; by hand, the rotation exp([v x]) of the
    rotation vector v above (scipy's Rotation), A's axes its columns."""
    from scipy.spatial.transform import Rotation
    path = tmp_path / "gyro.al"
    path.write_text(f"NEWTONIAN N\nBODIES A\nVARIABLES U'\n{rate}\nINPUT TFINAL = 1, "
                    "INTEGSTP = 0.01\nOUTPUT T, U\nCODE ODE() gyro.c\n")
    model = autolev.load(path)
    m = animation.motion(model, model.simulate(), max_frames=11)
    assert m.names == ["A", "A1>", "A2>", "A3>"] and m.kinds == [1, 2, 3]
    assert m.notes == ["A's orientation in N is not defined: its axes start along N's "
                       "and turn with its angular velocity"]
    assert np.allclose(m.xyz[0, 1:], np.eye(3), atol=1e-12)
    t = m.times[-1]
    axes = Rotation.from_rotvec(final(t)).as_matrix()
    assert np.allclose(m.xyz[-1, 1:], axes.T, atol=1e-4)


def test_a_figure_with_no_fixed_point_or_several_says_where_it_is_drawn(tmp_path):
    path = tmp_path / "loose.al"
    path.write_text("NEWTONIAN N\nFRAMES A\nPOINTS O, P\nVARIABLES TH'\nCONSTANTS L\n"
                    "SIMPROT(N, A, 3, TH)\nTH' = 1\nP_O_P> = L*A1>\n"
                    "INPUT L = 1, TFINAL = 1\nOUTPUT T, TH\nCODE ODE() loose.c\n")
    model = autolev.load(path)
    m = animation.motion(model, model.simulate(), max_frames=3)
    assert m.notes == ["no point of O, P is fixed in N: drawn with O at the origin"]
    assert np.allclose(m.xyz[:, 0], 0)
    path.write_text("NEWTONIAN N\nFRAMES A\nPOINTS O1, O2, P1, P2\nVARIABLES TH'\n"
                    "CONSTANTS L\nSIMPROT(N, A, 3, TH)\nTH' = 1\nV_O1_N> = 0>\nV_O2_N> = 0>\n"
                    "P_O1_P1> = L*A1>\nP_O2_P2> = L*A2>\n"
                    "INPUT L = 1, TFINAL = 1\nOUTPUT T, TH\nCODE ODE() loose.c\n")
    model = autolev.load(path)
    m = animation.motion(model, model.simulate(), max_frames=3)
    assert m.notes == ["O1, O2 are fixed in N with no position from NO or each other: "
                       "drawn at the origin"]
    assert m.names == ["O1", "P1", "O2", "P2"] and m.edges == [(0, 1), (2, 3)]


def test_the_gif_says_how_far_it_is(monkeypatch):
    import io
    from autolev.engine import progress
    clock = iter(range(0, 1000, 3))               # three seconds between two looks
    monkeypatch.setattr(progress.time, "monotonic", lambda: next(clock))
    stream = io.StringIO()                        # not a terminal: a line every 5 s
    report = progress.Progress(stream, "p.gif", 0, 40, says=animation_output.FRAMES)
    for k in range(1, 41):
        report.update(k)
    report.done()
    lines = stream.getvalue().splitlines()
    assert lines[0] == "  p.gif: frame 1 of 40 (2%), 3.0 s"
    assert lines[1] == "  p.gif: frame 3 of 40 (8%), 9.0 s" and len(lines) == 20


def test_autolev_animate_says_when_it_writes_no_gif(tmp_path, monkeypatch, capsys):
    from autolev import cli
    monkeypatch.setattr(cli.run, "has_matplotlib", lambda: False)
    code = cli.main(["animate", str(EXAMPLES / "double_pendulum.al"), "--out", str(tmp_path),
                     "--tfinal", "0.2", "-q"])
    assert code == 0
    assert "note: no GIF: it needs matplotlib" in capsys.readouterr().err
    assert (tmp_path / "double_pendulum.html").exists()
    assert not (tmp_path / "double_pendulum.gif").exists()


NODE_CANVAS = """
const calls = [];
const fakeContext = new Proxy({}, {
  get: (o, k) => k in o ? o[k] : (k === "measureText" ? (t => ({width: 7 * t.length}))
       : (...a) => calls.push([k, ...a])),
  set: (o, k, v) => {
    o[k] = v;
    if (k === "strokeStyle") calls.push(["strokeStyle", v]);
    return true; }
});
const elements = {
  motion: {textContent: DATA}, view: {getContext: () => fakeContext, width: 0, height: 0},
  time: {}, label: {}, play: {}};
global.document = {getElementById: id => elements[id]};
global.window = {innerWidth: 800, innerHeight: 640};
global.setInterval = () => 0;
"""


def page_calls(m, tmp_path) -> list:
    """The canvas calls of the page's script drawing its first frame, under Node.js."""
    import json
    import re
    page = animation_output.write_html(m, tmp_path / "m.html", "m").read_text()
    data = re.search(r'<script id="motion" type="application/json">(.*?)</script>', page,
                     re.S).group(1)
    script = page.rsplit("<script>", 1)[1].split("</script>")[0]
    program = (NODE_CANVAS.replace("DATA", json.dumps(data)) + script
               + "\nconsole.log(JSON.stringify(calls));")
    (tmp_path / "run.js").write_text(program)
    out = subprocess.run(["node", str(tmp_path / "run.js")], capture_output=True, text=True,
                         timeout=60, check=True).stdout
    return json.loads(out)


needs_node = pytest.mark.skipif(shutil.which("node") is None,
                                reason="needs Node.js to run the page's script")


@needs_node
def test_the_pages_script_draws_the_segments_and_the_labels_that_fit(tmp_path):
    m = animation.Motion("N", ["NO", "P1", "P2", "P3"], [(0, 1), (1, 2)], [2],
                         np.array([0.0]), np.array([[[0, 0, 0], [1, 0, 0], [2, 0, 0],
                                                     [2.001, 0, 0]]]), labelled=[1, 0, 2, 3])
    calls = page_calls(m, tmp_path)
    strokes = [c[1] for c in calls if c[0] == "strokeStyle"]
    assert strokes.count(animation_output.COLOURS[animation.SEGMENT]) == 2
    assert not set(animation_output.GRID_COLOURS.values()) & set(strokes)   # a view that stays
    texts = [c[1] for c in calls if c[0] == "fillText"]
    # P3 sits 1 mm from P2: its label would cover P2's, drawn before it is not;
    # N's axes in the corner: N1> and N2> as lines, N3> toward the viewer as a dot
    assert [t for t in texts if t in m.names] == ["P1", "NO", "P2"]
    assert "\u2299" in texts and {"N1>", "N2>", "N3>"} <= set(texts)


@needs_node
def test_the_pages_script_draws_the_grid_a_following_view_moves_over(tmp_path):
    # a 1 m rod that travels 10 m along N1 in two frames: a view 1.1 m wide about the
    # rod's middle (0.5, 0), a grid 0.2 m apart (1.1 / 4 = 0.275, nearest 0.2) drawn a
    # width either side: x = -0.6 ... 1.6 (12 lines, majors at 0 and 1), y = -1.1 ...
    # 1.1 (11 lines, majors at -1, 0, 1)
    times = np.array([0.0, 1.0])
    xyz = np.array([[[0, 0, 0], [1, 0, 0]], [[10, 0, 0], [11, 0, 0]]])
    m = animation.Motion("N", ["A", "B"], [(0, 1)], [], times, xyz)
    assert m.follows and m.grid()["step"] == 0.2
    strokes = [c[1] for c in page_calls(m, tmp_path) if c[0] == "strokeStyle"]
    grid = [c for c in strokes if c in animation_output.GRID_COLOURS.values()]
    assert len(grid) == 12 + 11 and grid.count(animation_output.GRID_COLOURS[True]) == 2 + 3


# -- real sprint and gait models -------------------------------------------------------------
# gait2de's segments, driven at constant joint rates by a CODE ODE of our own (the model
# itself writes only a CODE ALGEBRAIC of its dynamics): its parameters become constants
GAIT_DRIVE = """
q1'' = 0
q2'' = 0
q3'' = 0
q4'' = 0
q5'' = 0
q6'' = 0
q7'' = 0
q8'' = 0
q9'' = 0
Input par__TrunkMass = 50, par__TrunkInertia = 3, par__TrunkCMy = 0.3, par__ThighMass = 7
Input par__ThighInertia = 0.1, par__ThighCMy = -0.19, par__ThighLen = 0.44
Input par__ShankMass = 3, par__ShankInertia = 0.05, par__ShankCMy = -0.19
Input par__ShankLen = 0.44, par__FootMass = 1, par__FootInertia = 0.01, par__FootCMx = 0.05
Input par__FootCMy = -0.04, par__ContactY = -0.07, par__ContactHeelX = -0.06
Input par__ContactToeX = 0.15, gravity = 9.81, par__ContactStiff = 0, par__ContactDamp = 0
Input par__ContactY0 = 0, par__ContactV0 = 0, par__ContactFric = 0
Input q2 = 0.93, q1' = 1.3, q4 = -0.5, q4' = 2, q5' = -2, q7 = 0.4, q7' = -2, q8 = -0.6
Input q8' = 1, tfinal = 0.5, integstp = 0.005
Output T, q1
Code ODE() gaitkin.c
"""


def gait2de_kinematics(corpus, tmp_path):
    lines = (corpus / "csu-hmc+gait2d/algait2de/gait2de.al").read_text().splitlines()
    kept = lines[:next(k for k, line in enumerate(lines) if line.startswith("contact("))]
    text = "\n".join(kept).replace("Variables par__", "Constants par__").replace(
        "Variables   gravity", "Constants gravity")
    path = tmp_path / "gaitkin.al"
    path.write_text(text + GAIT_DRIVE)
    return path, None


def sprint_7segv2(corpus, tmp_path):
    folder = corpus / "TomRottier+SprintingModel/Model/7segv2"
    return folder / "7segsprint.al", folder / "base/7segsprint.in"


@pytest.mark.corpus
@pytest.mark.parametrize("case, fixed, joints, up", [
    (gait2de_kinematics, "GroundO", ["Hip", "RKnee", "RAnkle", "LKnee", "LAnkle", "RToe"],
     [0, 1, 0]),                                  # Gravity(-gravity*Ground2>)
    (sprint_7segv2, "O", [f"P{k}" for k in range(1, 10)], [0, 1, 0]),   # G*N2>, G = -9.81
])
def test_real_models_are_drawn_as_skeletons(corpus, tmp_path, case, fixed, joints, up):
    path, infile = case(corpus, tmp_path)
    model = autolev.load(path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")           # the sprint's .in: names, DEG/S rates
        result = model.simulate(infile=infile)
    m = animation.motion(model, result)
    assert set(joints) <= set(m.names) and fixed not in m.names
    # a forest: no edge closes a cycle; no point is the hub of a fan
    parent = list(range(len(m.names)))

    def root(k):
        while parent[k] != k:
            k = parent[k]
        return k
    for a, b in m.edges:
        assert root(a) != root(b), (m.names[a], m.names[b])
        parent[root(a)] = root(b)
    degree = np.bincount(np.ravel(m.edges), minlength=len(m.names))
    assert degree.max() <= 6, m.names[int(degree.argmax())]
    assert np.allclose(m.basis[1], up)
    lo, hi = m.view_box()
    points = m.picture.reshape(-1, 3)
    assert np.all(lo <= points.min(axis=0)) and np.all(points.max(axis=0) <= hi)


CHAIN_OF_MASS_CENTRES = """NEWTONIAN N
BODIES A, B, C
MOTIONVARIABLES' Q{3}', U{3}'
CONSTANTS L1, L2, L3, M, G
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
SIMPROT(N, C, 3, Q3)
Q1' = U1
Q2' = U2
Q3' = U3
P_NO_AO> = L1/2*A1>
P_NO_BO> = L1*A1> + L2/2*B1>
P_NO_CO> = L1*A1> + L2*B1> + L3/2*C1>
V_AO_N> = DT(P_NO_AO>, N)
V_BO_N> = DT(P_NO_BO>, N)
V_CO_N> = DT(P_NO_CO>, N)
MASS A = M, B = M, C = M
INERTIA A, 0, 0, M*L1^2/12
INERTIA B, 0, 0, M*L2^2/12
INERTIA C, 0, 0, M*L3^2/12
{centre}
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L1 = 1, L2 = 0.8, L3 = 0.6, M = 1, G = 9.81, Q1 = 0.5, Q2 = 1, Q3 = 1.5
INPUT TFINAL = 0.5, INTEGSTP = 0.1
OUTPUT Q1, Q2, Q3
CODE DYNAMICS() chain.c
"""


@pytest.mark.parametrize("centre", ["", "POINTS CM\nP_NO_CM> = CM(NO)"])
def test_a_chain_known_by_its_mass_centres_is_drawn_through_its_joints(tmp_path, centre):
    # no joint is a named point: each link's end is where the model's next part begins
    # (L1*A1>, then L2*B1> on), found along the links to the mass centres; the system's
    # mass centre, a weighted sum, passes no joint (its link is drawn whole)
    path = tmp_path / "chain.al"
    path.write_text(CHAIN_OF_MASS_CENTRES.replace("{centre}", centre))
    model = autolev.load(path)
    result = model.simulate()
    m = animation.motion(model, result, max_frames=6)
    names = ["NO", "AO", "A/B", "BO", "B/C", "CO"]
    assert [n for n in m.names if n != "CM"] == names
    assert sorted((m.names[a], m.names[b]) for a, b in m.edges if "CM" not in
                  (m.names[a], m.names[b])) == [
        ("A/B", "B/C"), ("A/B", "BO"), ("B/C", "CO"), ("NO", "A/B"), ("NO", "AO")]
    drawn = [m.names.index(n) for n in names]
    for k in range(len(m.times)):
        q1, q2, q3 = (np.interp(m.times[k], result.t, result.outputs[0][n])
                      for n in ("Q1", "Q2", "Q3"))
        a, b, c = ([math.cos(q), math.sin(q), 0.0] for q in (q1, q2, q3))
        joint_ab = np.array(a)
        joint_bc = joint_ab + 0.8 * np.array(b)
        by_hand = [np.zeros(3), 0.5 * np.array(a), joint_ab, joint_ab + 0.4 * np.array(b),
                   joint_bc, joint_bc + 0.3 * np.array(c)]
        assert np.allclose(m.xyz[k][drawn], by_hand, atol=1e-6)
