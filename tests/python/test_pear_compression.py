"""Scene S6 (paper Section 3.3, Fig. 9; roundedmesh_study.pear_compression, scripts/validation/
validate_pear_compression.py): the pear of shapes.json,
70 mm high, pressed by a rigid plate, against Hertz's solution at the smooth shape's local principal radii."""
import numpy as np

from roundedmesh_study import hertz_reference as hr
from roundedmesh_study import pear_compression as s6
from roundedmesh_study.analytic import effective_modulus, nrmse
from roundedmesh_study.shape_error import rounded_mesh



# The bound: within 2 % (NRMSE) at the paper's node count (486) with the curvature computed from the mesh, for
# the paper's circular contact and the elliptical one; measured 0.53 % and 0.80 % (0.22 % with the exact curvature).
# The contact is on one of the pear's spheres (the docstring of the script says why), so the reference is Hertz's
# with equal radii, an independent closed form (elliptical_hertz_force at ratio 1).
def test_the_pear_on_a_plate_follows_hertz_at_the_papers_node_count():
    s = s6.scale_factor()
    deltas = s6.INDENTATION / s * np.arange(1, s6.SAMPLES + 1) / s6.SAMPLES
    orientation, geometry = s6.contact_pose(1.6, 400, 1, 486)
    assert geometry.r_major / geometry.r_minor < 1 + 1e-6   # the sphere: the paper's 1.6 is not on this pear
    hertz = hr.reference_force(effective_modulus(s6.PEAR, s6.PLATE), geometry.r_major, geometry.r_minor, deltas)
    for curvature in ("computed", "prescribed"):
        representation = rounded_mesh("pear", 486, curvature)
        for model in s6.MODELS:
            assert nrmse(s6.press(representation, orientation, deltas, model), hertz) <= 0.02, (curvature, model)
