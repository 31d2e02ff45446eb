"""Where does a settled packing's spin come from? The spheroid's S1 packing restarted under cases that each change one
thing (time step, damping, normal law, spins zeroed), its kinetic energy followed (issue 41).

    /usr/bin/python3 scripts/validation/spin_energy.py [--shape spheroid] [--poses CSV] [--time 0.125]
        [--cases default dt/4 undamped energy "energy, undamped" ...] [--output out/spin_energy]

The code, and what it writes: roundedmesh_study.spin_energy.
"""
import sys

from roundedmesh_study.spin_energy import main

if __name__ == "__main__":
    main(sys.argv[1:])
