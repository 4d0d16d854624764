"""ssimarch.porosity against closed forms for one sphere, and numpy input edge cases."""
import numpy as np
import pytest

import ssimarch
from ssimarch import porosity

R = 2.0  # container radius
A = 0.5  # sphere radius (d = 1), centred on the axis at the origin; default height range [-A, A]
ONE = np.array([[0.0, 0.0, 0.0, 2 * A]])


def test_bulk_is_one_minus_sphere_over_cylinder():
    # (4/3 pi A^3) / (pi R^2 2A) = 2 A^2 / (3 R^2)
    assert porosity.bulk(ONE, R) == pytest.approx(1.0 - 2.0 * A * A / (3.0 * R * R), abs=1e-9)


def test_radial_profile_of_one_sphere():
    r, eps = porosity.radial(ONE, R, 40)
    assert r.shape == eps.shape == (40,) and r.dtype == eps.dtype == np.float64
    np.testing.assert_allclose(r, R * np.arange(1, 41) / 40, rtol=0, atol=1e-15)
    # The cylinder of radius r meets the sphere over |z| < sqrt(A^2 - r^2) of the height 2A.
    expected = 1.0 - np.sqrt(np.clip(A * A - r * r, 0.0, None)) / A
    np.testing.assert_allclose(eps, expected, rtol=0, atol=1e-7)


def test_axial_profile_of_one_sphere():
    z, eps = porosity.axial(ONE, R, 10)
    np.testing.assert_allclose(z, -A + 2 * A * (np.arange(10) + 0.5) / 10, atol=1e-15)
    # The disc of radius sqrt(A^2 - z^2) in the container's cross-section of area pi R^2.
    np.testing.assert_allclose(eps, 1.0 - (A * A - z * z) / (R * R), rtol=0, atol=1e-7)


def test_height_range_is_used():
    # The sphere fills only half of [-A, 3A]: the bulk porosity doubles its distance to 1.
    full = porosity.bulk(ONE, R)
    half = porosity.bulk(ONE, R, height_range=(-A, 3 * A))
    assert 1.0 - half == pytest.approx((1.0 - full) / 2.0, abs=1e-9)


def bed() -> np.ndarray:
    rng = np.random.default_rng(7)
    xyz = rng.uniform(-1.0, 1.0, size=(12, 3))
    return np.hstack([xyz, np.full((12, 1), 0.5)])


def test_float32_and_fortran_order_give_the_same_profile():
    b = bed().astype(np.float32).astype(np.float64)  # values exactly representable in float32
    r0, e0 = porosity.radial(b, R, 8)
    for variant in (b.astype(np.float32), np.asfortranarray(b), b[:, [0, 1, 2, 3]][::1]):
        r1, e1 = porosity.radial(variant, R, 8)
        np.testing.assert_array_equal(r0, r1)
        np.testing.assert_allclose(e1, e0, rtol=0, atol=1e-12)  # threads may sum in another order
    # A non-contiguous view (every other row) is the same as its copy.
    _, e2 = porosity.radial(b[::2], R, 8)
    _, e3 = porosity.radial(np.ascontiguousarray(b[::2]), R, 8)
    np.testing.assert_allclose(e2, e3, rtol=0, atol=1e-12)


def test_spherocylinder_of_length_zero_is_a_sphere():
    sc = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2 * A, 0.0]])
    assert porosity.bulk(sc, R) == pytest.approx(porosity.bulk(ONE, R), abs=1e-12)


def test_empty_array_is_a_clear_error():
    with pytest.raises(ssimarch.InputError, match="no particles"):
        porosity.radial(np.empty((0, 4)), R)


@pytest.mark.parametrize("shape", [(3, 3), (5,), (2, 4, 1), (4, 5)])
def test_wrong_shape_is_a_clear_error(shape):
    with pytest.raises(ssimarch.InputError, match=r"N×4 .*got shape \(") as e:
        porosity.radial(np.ones(shape), R)
    assert isinstance(e.value, ValueError)


def test_non_numeric_input_and_bad_job_are_errors():
    with pytest.raises((TypeError, ValueError)):
        porosity.radial(np.array([["a", "b", "c", "d"]]), R)
    with pytest.raises(ssimarch.InputError, match="container_radius"):
        porosity.radial(ONE, -1.0)
    with pytest.raises(ssimarch.InputError, match="radial_points"):
        porosity.radial(ONE, R, -3)


def test_a_packing_file_is_read(tmp_path):
    f = tmp_path / "bed.csv"
    f.write_text("x,y,z,d\n0,0,0,1\n")
    assert porosity.bulk(f, R) == pytest.approx(porosity.bulk(ONE, R), abs=1e-12)
