"""Bad input to the gear drive: one TmmError with a message naming the problem and the fix."""

import pytest

from tmm_cli.errors import TmmError
from tmm_cli.gears.design import design_gears, parse_ratio


@pytest.mark.parametrize("text", ["13/", "a/b", "0/4", "-3/4", "", "13/0", "3.5/2", "13//4", "/4"])
def test_parse_ratio_rejects_malformed(text):
    with pytest.raises(TmmError) as e:
        parse_ratio(text)
    assert "13/4" in str(e.value)  # the message shows the right form


def test_parse_ratio_accepts():
    assert parse_ratio("13/4") == (13, 4)
    assert parse_ratio(" 53 / 5") == (53, 5)
    assert parse_ratio("11") == (11, 1)


@pytest.mark.parametrize("rpm", [0, -40, float("nan")])
def test_crank_speed_must_be_positive(rpm):
    with pytest.raises(TmmError) as e:
        design_gears(1000, rpm)
    assert "crank" in str(e.value) and "--crank-rpm" in str(e.value)


@pytest.mark.parametrize("rpm", [961, 2000])
def test_crank_speed_above_960_has_no_motor(rpm):
    with pytest.raises(TmmError) as e:
        design_gears(1000, rpm)
    msg = str(e.value)
    assert "2880" in msg and "960" in msg and "\n" not in msg


def test_cam_speed_zero():
    with pytest.raises(TmmError):
        design_gears(0, 220)


def test_tolerance_too_tight_names_the_closest_ratio():
    with pytest.raises(TmmError) as e:
        design_gears(1000, 67, tolerance_pct=0.0)
    msg = str(e.value)
    assert "closest" in msg and "--tolerance" in msg
    # the suggested tolerance does work
    tol = float(msg.split("--tolerance ")[1].split()[0])
    r = design_gears(1000, 67, tolerance_pct=tol)
    assert abs(r.planetary.ratio_error_pct) <= tol + 1e-9


def test_negative_tolerance():
    with pytest.raises(TmmError):
        design_gears(1000, 220, tolerance_pct=-1)


def test_forced_ratio_outside_tolerance():
    with pytest.raises(TmmError) as e:
        design_gears(1000, 67, ratio=(13, 4))
    assert "13/4" in str(e.value) and "--tolerance" in str(e.value)


def test_forced_ratio_not_realisable():
    # 1 + z_n/z_k = 3307/1000 needs z_k a multiple of 1000
    with pytest.raises(TmmError) as e:
        design_gears(1000, 220, ratio=(3307, 1000))
    assert "3307/1000" in str(e.value)


def test_forced_planets_impossible():
    with pytest.raises(TmmError) as e:
        design_gears(1000, 220, planets=40)
    assert "--planets" in str(e.value)


def test_forced_planets_bad_value():
    with pytest.raises(TmmError):
        design_gears(1000, 220, planets=0)


def test_negative_torque():
    with pytest.raises(TmmError):
        design_gears(1000, 220, torque_nm=-5)
