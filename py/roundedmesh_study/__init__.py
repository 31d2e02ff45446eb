"""roundedmesh_study: the code of the validation and the studies, not needed to build or run a scene. It uses the
package roundedmesh, which never imports it; import what is needed:

    from roundedmesh_study import validation, analytic

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
    model_table       the study's data (speed_vs_error.json) and the table rm.cheapest_model reads, made from it
    model_check       rm.cheapest_model's choice for a study shape's fine mesh, measured as the study measures
    peers             YADE's own representations of the reference shapes (clumps, level sets, spheres) for S1
                      (doc/s1-packing.md)
    sphere_fill       a clump for any mesh: the greedy inscribed-sphere fill
    mesh_distance     the exact signed distance to a closed triangle mesh (level sets and fills of any mesh)
    benchmarking      the machine's description and step timings for the benchmark scripts (doc/benchmarks.md)

The scripts that use them are in scripts/validation, scripts/studies and scripts/benchmarks (scripts/README.md);
each parses its options and calls a module here. A study that runs a scene whole runs its script as a command
(SCRIPTS).
"""
import os

# The repository's scripts/ folder, from this package's source (build/python links to it).
SCRIPTS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__)))), "scripts")
