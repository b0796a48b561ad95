"""The specific-volume error of interior fluid particles: each particle's Voronoi cell
volume against d0^D, in percent, positive for expansion (the sign of eq. 22 of
docs/method.md, section 12.3).

Why next to eq. 22: eq. 22 reads density from the kernel sum, whose value at a fixed number
density depends on how the particles are arranged. With the cubic spline at h = 1.2 d0 a 3D
arrangement relaxed by the shift reads about 0.3 % under-dense at exactly the lattice's
number density, a 2D one about 0 (docs/validation.md, "Taylor-Green vortex"), so eq. 22 cannot
compare the two dimensions to 0.2 pp. The Voronoi cell volume is the volume a particle
occupies, whatever the arrangement: the lattice reads 0 and a uniform stretch by (1 + e)
reads (1 + e)^D - 1 (to Qhull's joggle, below 1e-4 %).

Interior particles (fluid, class 0) have closed cells: wall particles bound them at walls,
the vicinity band at the free surface. Periodic directions are closed by copying the
particles within `margin` spacings of each face across it. scipy.spatial.Voronoi (Qhull)
builds the cells, ConvexHull measures them."""
import numpy as np


def errors(particles, d0, dimension, periodic=(), margin=4.0):
    """Per-particle specific-volume errors [%] of the interior fluid particles, and the
    number of interior cells that were open (not measured; 0 when the walls and the band
    close the interior). particles: shizukutest.read_vtp's dictionary; periodic:
    (axis, lo, hi) of each periodic direction."""
    from scipy.spatial import ConvexHull, Voronoi

    pts = np.asarray(particles["position"], dtype=float)[:, :dimension]
    interior = np.where((particles["type"] == 0) & (particles["surface"] == 0))[0]
    images = [pts]
    for axis, lo, hi in periodic:
        length = hi - lo
        base = np.concatenate(images)
        for side, shift in ((base[:, axis] < lo + margin * d0, length), (base[:, axis] > hi - margin * d0, -length)):
            copy = base[side].copy()
            copy[:, axis] += shift
            images.append(copy)
    # QJ: wall particles on an exact lattice make cospherical point sets, on which Qhull's
    # facet merges fail ("wide merge" at d0 = 1 cm, "twisted facet" at 5 mm, 2026-12-03);
    # joggling the input moves the mean cell volume by round-off (4e-7 % on a 3D lattice
    # of 10k particles, 6e-5 % on one of 110k, 1e-10 % on a disordered set).
    cells = Voronoi(np.concatenate(images), qhull_options="Qbb QJ")
    out, open_cells = [], 0
    for k in interior:
        region = cells.regions[cells.point_region[k]]
        if not region or -1 in region:
            open_cells += 1
            continue
        out.append(ConvexHull(cells.vertices[region]).volume)
    return 100.0 * (np.array(out) / d0 ** dimension - 1.0), open_cells
