"""One tube of every kind, for physics that holds for any tube (the ``tubes`` fixture of
conftest.py; tests that add their own tubes import TUBES from here)."""

from electrogrowth.model.layers import Layer, LinearGrowth, Tube
from electrogrowth.model.materials import Material, gent, mooney_rivlin

#: one tube of every kind, for physics that holds for any tube (the ``tubes`` fixture)
TUBES = {
    "uniform": Tube.uniform(1.5, 2.0, growth=1.1, stretch=1.05, voltage=0.3),
    "two-layer": Tube(
        (Layer(1.2, shear_modulus=4.0, growth=(1.0, 1.15, 1.0)), Layer(1.8, gent(50.0))),
        length=2.0,
        voltage=0.2,
    ),
    "graded": Tube(
        (Layer(1.6, mooney_rivlin(0.3), growth=LinearGrowth(1.0, 1.6, (1.0, 1.12, 1.0), 1.0)),),
        length=2.0,
        stretch=1.02,
    ),
    "pressurised": Tube((Layer(1.5),), length=2.0, inner_pressure=0.08, outer_pressure=0.02),
    "force-controlled": Tube(
        (Layer(1.3, shear_modulus=3.0), Layer(1.7, permittivity=2.0)),
        length=2.0,
        axial_force=-0.5,
        voltage=0.1,
    ),
}

#: the mucosal bilayer of benchmarks/layered_bench.py (mu 10 on 1, hoop growth, P_i 0.05)
MUCOSA = Tube(
    (Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)),
    length=3.0,
    voltage=0.3,
    inner_pressure=0.05,
)
#: its force-controlled twin (free closed ends, P_i 0.03): the critical voltage of (0, 1) lies
#: 6e-7 below the limit point of the voltage branch, where r_i moves like a square root
FORCE_BILAYER = Tube(
    (Layer(1.1, shear_modulus=10.0, growth=(1.0, 1.2, 1.0)), Layer(2.0)),
    length=3.0,
    axial_force=0.0,
    voltage=0.2,
    closed_ends=True,
    inner_pressure=0.03,
)

#: an energy text (no built-in family) used by several probe tubes
TEXT = Material("txt", "0.3*(I1-3) + 0.2*(I2-3) + 0.01*(I1-3)**2 + I5/2")
#: probe round 8a's four layers: a soft Gent core, a skin 1e4 times as stiff, an energy
#: text and a soft Mooney-Rivlin layer (its collapse (2, 0) and voltage window (6, 8))
FOUR_LAYERS = Tube(
    [
        Layer(1.2, material=gent(50.0), shear_modulus=1e-2),
        Layer(1.201, shear_modulus=100.0),
        Layer(1.6, material=TEXT),
        Layer(2.2, material=mooney_rivlin(0.2), shear_modulus=0.01),
    ],
    length=2.0,
    stretch=1.0,
)
