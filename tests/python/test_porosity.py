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


def sphere_volume_inside_cylinder(rho):
    """Volume of the ball of radius A on the axis within distance rho of the axis (rho <= A):
    4/3 pi (A^3 - (A^2 - rho^2)^(3/2))."""
    rho = np.minimum(rho, A)
    return 4.0 / 3.0 * np.pi * (A**3 - (A * A - rho * rho) ** 1.5)


def test_bins_of_one_sphere_are_annulus_averages():
    r0, r1, eps = porosity.bins(ONE, R, 8)
    np.testing.assert_allclose(r0, R * np.arange(8) / 8, atol=1e-15)
    np.testing.assert_allclose(r1, R * np.arange(1, 9) / 8, atol=1e-15)
    solid = sphere_volume_inside_cylinder(r1) - sphere_volume_inside_cylinder(r0)
    np.testing.assert_allclose(eps, 1.0 - solid / (np.pi * (r1**2 - r0**2) * 2 * A), rtol=0, atol=1e-7)
    with pytest.raises(ssimarch.InputError, match="bins"):
        porosity.bins(ONE, R, 0)


def test_map_is_the_azimuthal_average_on_circles():
    # A sphere of radius A centred at distance c from the axis: at height z its section is the disc of
    # radius a = sqrt(A^2 - z^2) about (c, 0); the circle of radius r runs inside it over the angle
    # 2 acos((r^2 + c^2 - a^2) / (2 r c)).
    c = 0.8
    off = np.array([[c, 0.0, 0.0, 2 * A]])
    r, z, eps = porosity.map(off, R, 16, 6)
    assert r.shape == (16,) and z.shape == (6,) and eps.shape == (6, 16)
    np.testing.assert_allclose(r, R * (np.arange(16) + 0.5) / 16, atol=1e-15)
    np.testing.assert_allclose(z, -A + 2 * A * (np.arange(6) + 0.5) / 6, atol=1e-15)
    rr, zz = np.meshgrid(r, z)
    a2 = A * A - zz * zz
    cosine = np.clip((rr * rr + c * c - a2) / (2 * rr * c), -1.0, 1.0)
    np.testing.assert_allclose(eps, 1.0 - np.arccos(cosine) / np.pi, rtol=0, atol=1e-7)


def test_pack_spheres_is_a_valid_deterministic_bed():
    d, radius = 1.0, 2.5
    ps, info = porosity.pack("spheres", radius, 60, diameter=d, seed=5)
    assert ps.shape == (60, 4) and info["placed"] == 60 and info["container_radius"] == radius
    assert np.all(ps[:, 3] == d)
    # Inside the container and above the floor, no two spheres overlapping (contact tolerance 1e-9 d).
    assert np.all(np.hypot(ps[:, 0], ps[:, 1]) <= radius - d / 2 + 1e-9)
    assert np.all(ps[:, 2] >= d / 2 - 1e-9)
    gaps = np.linalg.norm(ps[:, None, :3] - ps[None, :, :3], axis=-1) + np.eye(60) * 10
    assert gaps.min() >= d * (1 - 1e-9) and info["max_overlap"] <= 1e-9 * d
    # The bed is z in [0, top of the bed]: every sphere wholly inside, so eps = 1 - N (pi d^3/6) / (pi R^2 H).
    z0, z1 = info["height_range"]
    assert z0 == 0.0 and z1 == pytest.approx(ps[:, 2].max() + d / 2)
    closed = 1.0 - 60 * (np.pi * d**3 / 6) / (np.pi * radius**2 * (z1 - z0))
    assert info["bulk_porosity"] == pytest.approx(closed, abs=1e-9)
    assert porosity.bulk(ps, radius, height_range=(z0, z1)) == pytest.approx(closed, abs=1e-8)
    again, _ = porosity.pack("spheres", radius, 60, diameter=d, seed=5)
    np.testing.assert_array_equal(ps, again)
    other, _ = porosity.pack("spheres", radius, 60, diameter=d, seed=6)
    assert not np.array_equal(ps, other)


def test_pack_spherocylinders():
    ps, info = porosity.pack("spherocylinders", 3.0, 25, diameter=0.5, length=1.0, height=4.0, seed=2)
    assert ps.shape == (info["placed"], 8) and info["placed"] == 25
    np.testing.assert_allclose(np.linalg.norm(ps[:, 3:6], axis=1), 1.0, atol=1e-12)
    np.testing.assert_array_equal(ps[:, 6], 0.5)
    np.testing.assert_array_equal(ps[:, 7], 1.0)
    assert info["height_range"] == (0.0, 4.0)
    # The caps' centres lie within R - d/2 of the axis and within the height (RSA places particles inside).
    for sign in (1, -1):
        cap = ps[:, :3] + sign * 0.5 * ps[:, 7:8] * ps[:, 3:6]
        assert np.all(np.hypot(cap[:, 0], cap[:, 1]) <= 3.0 - 0.25 + 1e-9)
        assert np.all((cap[:, 2] >= 0.25 - 1e-9) & (cap[:, 2] <= 4.0 - 0.25 + 1e-9))
    assert porosity.bulk(ps, 3.0, height_range=(0.0, 4.0)) == pytest.approx(info["bulk_porosity"], abs=1e-8)


def test_pack_errors_name_the_keyword():
    with pytest.raises(ssimarch.InputError, match="^length: applies to spherocylinders only"):
        porosity.pack("spheres", 3.0, 10, length=1.0)
    with pytest.raises(ssimarch.InputError, match="^diameter_max: applies to spheres only"):
        porosity.pack("spherocylinders", 3.0, 10, diameter_max=2.0)
    with pytest.raises(ssimarch.InputError, match="^kind: "):
        porosity.pack("cubes", 3.0)
    with pytest.raises(ssimarch.InputError, match="^count: "):
        porosity.pack("spheres", 3.0, 0)
    with pytest.raises(ssimarch.InputError, match="container_radius"):
        porosity.pack("spheres", -1.0, 10)


def test_de_klerk_is_the_published_formula():
    x = np.array([0.0, 0.3, 0.637, 1.0, 2.5])
    eb = 0.39
    expected = np.where(x <= 0.637, 2.14 * x**2 - 2.53 * x + 1,
                        eb + 0.29 * np.exp(-0.6 * x) * np.cos(2.3 * np.pi * (x - 0.16)) + 0.15 * np.exp(-0.9 * x))
    np.testing.assert_allclose(porosity.de_klerk(x, eb), expected, rtol=1e-14)


def test_overlapping_particles_are_a_warning_and_strict_is_the_warning_filter():
    # Issue 29: two overlapping spheres gave -0.146 with no word; issue 30: their common volume
    # counts once (the union), and the overlap is still said, as the CLI says it.
    two = np.array([[0.0, 0.0, 0.0, 1.0], [0.3, 0.0, 0.0, 1.0]])
    with pytest.warns(RuntimeWarning, match="pair of particles overlap.*counted once"):
        porosity.bulk(two, R)
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(RuntimeWarning):
            porosity.radial(two, R, 10)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        porosity.bulk(ONE, R)  # one sphere: no warning


def test_clumped_particles_overlap_inside_without_a_warning():
    # Issue 30: two particles of two overlapping spheres each; their own overlaps are by design.
    import warnings
    spheres = np.array([[0.0, 0, 0, 1], [0.4, 0, 0, 1], [1.5, 0, 0, 1], [1.9, 0, 0, 1]])
    ids = np.array([7, 7, 9, 9])
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # the CLI's --strict
        r, clumped = porosity.radial(spheres, 3.0, 12, clumps=ids)
    with pytest.warns(RuntimeWarning, match="2 pairs of particles overlap"):
        _, plain = porosity.radial(spheres, 3.0, 12)
    assert np.array_equal(clumped, plain)  # the profile is the union's either way
    # Particle 9 moved onto particle 7: an overlap between particles is said.
    touching = spheres - np.array([0.2, 0, 0, 0]) * np.array([[0], [0], [1], [1]])
    with pytest.warns(RuntimeWarning, match="1 pair of clumped particles overlap"):
        porosity.bulk(touching, 3.0, clumps=ids)
    with pytest.raises(ssimarch.InputError, match="clumps.*integer particle ids, got dtype float64"):
        porosity.bulk(spheres, 3.0, clumps=np.array([7.0, 7.0, 9.0, 9.5]))
    with pytest.raises(ssimarch.InputError, match="clumps.*4 particles"):
        porosity.bulk(spheres, 3.0, clumps=np.array([1, 2, 3]))


def test_overlapping_particles_count_once_unless_asked_otherwise():
    # The union's solid volume: two unit-diameter balls 0.3 apart share the lens
    # pi (a + b - D)^2 (D^2 + 2 D (a + b)) / (12 D) with a = b = 1/2, D = 0.3.
    import math
    import warnings
    two = np.array([[0.0, 0.0, 0.0, 1.0], [0.3, 0.0, 0.0, 1.0]])
    d = 0.3
    lens = math.pi * (1 - d) ** 2 * (d * d + 2 * d) / (12 * d)
    ball = math.pi / 6
    h = (-0.5, 0.5)
    volume = math.pi * R * R * 1.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        union = porosity.bulk(two, R, height_range=h, tolerance=1e-12)
        summed = porosity.bulk(two, R, height_range=h, tolerance=1e-12, overlaps="sum")
    assert (1 - union) * volume == pytest.approx(2 * ball - lens, abs=1e-10)
    assert (1 - summed) * volume == pytest.approx(2 * ball, abs=1e-10)
    with pytest.raises(ssimarch.InputError, match="overlaps: must be 'union'"):
        porosity.bulk(ONE, R, overlaps="both")


def test_particle_rows_follow_the_readers_rules():
    # Issue 29: a negative diameter was reported as a slab height range.
    with pytest.raises(ssimarch.InputError, match=r"particles\[1\]\[3\]: the diameter must be > 0, got -1"):
        porosity.bulk(np.array([[0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 2.0, -1.0]]), 2.0)
    rod = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0]])
    with pytest.raises(ssimarch.InputError, match=r"particles\[0\]\[3:6\]: the axis"):
        porosity.bulk(rod, 2.0)
    # A non-unit axis is the same rod as its unit one.
    a = porosity.bulk(np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 3.0, 1.0, 1.0]]), 2.0)
    b = porosity.bulk(np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0]]), 2.0)
    assert a == pytest.approx(b, abs=1e-12)


def test_defaults_are_the_clis():
    # One place for the defaults (pipeline/porosity_job.hpp, PorosityDefaults): the radial profile
    # at 200 radii like `ssimarch porosity` without --radii, to the CLI's tolerance of 1e-8.
    r, eps = porosity.radial(ONE, R)
    assert r.shape == (200,)
    np.testing.assert_allclose(r, R * np.arange(1, 201) / 200, rtol=0, atol=1e-15)
    expected = 1.0 - np.sqrt(np.clip(A * A - r * r, 0.0, None)) / A
    np.testing.assert_allclose(eps, expected, rtol=0, atol=1e-8)
