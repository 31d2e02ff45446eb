"""roundedmesh.study: the code of the validation and the studies, not needed to build or run a scene. It is not
imported by `import roundedmesh`; import what is needed:

    from roundedmesh.study import validation, analytic

or use it as an attribute, which imports the module on first use: `import roundedmesh as rm; rm.study.scenes.S3`.

    analytic          analytic references written independently of the compiled code: Hertz (spherical and
                      elliptical), the bouncing sphere, NRMSE (doc/validation.md)
    hertz_reference   Hertz's solution at a smooth shape's contact point (principal curvatures of the pear and
                      the gummy bear), the reference of the speed-against-error study
    validation        the body-body scenes (S2 pairs, S5) pressed together, against Hertz (doc/validation.md)
    scenes            the reference scenes S2, S3, S4 and the slope, built in O (doc/scenes.md)
    shape_error       the force error of a meshed shape and of YADE's representations against Hertz or the
                      half-space solution (doc/speed-vs-error.md)
    halfspace         the elastic half-space contact of any gap, the reference where Hertz does not hold
    grains            the study's shapes not made of spheres: a spheroid, a pill, a rounded tetrahedral grain
    model_choice      the cheapest model that meets a force error, for a study shape or any mesh; rm.cheapest_model
                      is its user entry point
    peers             YADE's own representations of the reference shapes (clumps, level sets, spheres) for S1
                      (doc/s1-packing.md)
    sphere_fill       a clump for any mesh: the greedy inscribed-sphere fill
    mesh_distance     the exact signed distance to a closed triangle mesh (level sets and fills of any mesh)
    benchmarking      the machine's description and step timings for the benchmark scripts (doc/benchmarks.md)

The scripts that use them are in scripts/validation, scripts/studies and scripts/benchmarks (scripts/README.md).
"""
import importlib

MODULES = ("analytic", "benchmarking", "grains", "halfspace", "hertz_reference", "mesh_distance", "model_choice",
           "peers", "scenes", "shape_error", "sphere_fill", "validation")


def __getattr__(name):
    """rm.study.<module> imports the module on first use (PEP 562)."""
    if name in MODULES:
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(MODULES))
