"""The long run of test_checkpoint.py, as a child process that can be killed: four rounded bodies falling on
a wall and onto each other, checkpointed every few steps, run to a fixed iteration; prints the final states
(positions, orientations, velocities, angular velocities of every body, as float.hex) as JSON.
    python3 checkpoint_child.py PATH STEPS EVERY fresh|resume [KILL_AT]
KILL_AT (optional): SIGKILL this process at the KILL_AT-th os.replace of the checkpoint's saves, "N:before"
or "N:after" it, to die at each stage of a save. Without it, only the parent's kill stops the run."""
import json
import os
import signal
import sys

import roundedmesh as rm
from yade import ForceResetter, NewtonIntegrator, O, utils

path, steps, every, mode = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]

if len(sys.argv) > 5:
    count, when = sys.argv[5].split(":")
    replace, calls = os.replace, [0]

    def dying_replace(source, target):
        calls[0] += 1
        if calls[0] == int(count) and when == "before":
            os.kill(os.getpid(), signal.SIGKILL)
        replace(source, target)
        if calls[0] == int(count) and when == "after":
            os.kill(os.getpid(), signal.SIGKILL)

    os.replace = dying_replace

if mode == "fresh":
    rubber = rm.HertzMaterial(young=1e6, poisson=0.4, density=2000, damping=1e-3, friction=0.3, tangential_damping=5)
    # 2562 nodes each: a scene whose save takes long enough for a random kill to land in it. Three bodies on
    # the wall, 0.1 mm deep in it and in each other, and one on top of two of them: contacts from the start.
    mesh = rm.Mesh.icosphere(0.01, 4)
    for x, y, z in [(0, 0, 0.0099), (0.0199, 0, 0.0099), (0, 0.0199, 0.0099), (0.00995, 0, 0.0271)]:
        rm.add_body(mesh, pos=(x, y, z), material=rubber)
    floor = O.bodies.append(utils.wall(0, axis=2, sense=1))
    rm.assign_material(floor, rubber)
    checkpoints = rm.checkpoint.Checkpointer(path, every_steps=every)
    O.engines = [checkpoints.engine(), ForceResetter(), rm.engine(), NewtonIntegrator(gravity=(0, 0, -9.81))]
    O.dt = 2e-5
else:
    rm.checkpoint.resume(path)
O.run(steps - O.iter, True)
states = {b.id: [[v.hex() for v in vector] for vector in
                 (b.state.pos, b.state.ori.toAxisAngle()[0], [b.state.ori.toAxisAngle()[1]], b.state.vel, b.state.angVel)]
          for b in O.bodies}
print(json.dumps({"iteration": O.iter, "states": states}))
