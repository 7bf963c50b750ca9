"""One tube of every kind, for physics that holds for any tube (the ``tubes`` fixture of
conftest.py; tests that add their own tubes import TUBES from here)."""

from electrogrowth.model.layers import Layer, LinearGrowth, Tube
from electrogrowth.model.materials import Material, gent, mooney_rivlin, neo_hookean

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


COUPI4 = Material("coupi4", "(I1-3)/2 + 0.45*I5 + 0.05*I4*(1 + 0.1*(I1-3))")
#: check round 28 (res_61 #12): coupi4 / i45 / NH, closed ends, force-controlled (the force
#: march's start, F 0; at F 247.25 the charge raises the residual of (*) outward of the
#: uncharged state and the voltage branch runs inward; the inflation threshold at V = 0
#: falls to P_i at F 248.218)
PULLED_TRILAYER = Tube(
    [
        Layer(R, m, shear_modulus=mu, permittivity=e, growth=g)
        for R, m, mu, e, g in (
            (2.2272094425672435, COUPI4,
             0.7976973554187421, 0.7977123344570403,
             (1.197043200303482, 1.1742760992873587, 1.0352749947621513)),
            (2.2695424970484774, Material("i45", "(I1-3)/2 + 0.3*I5 + 0.2*I4"),
             0.48727914480018003, 0.8154810072400097, (1.0904017401198194,) * 3),
            (2.5921515867038627, neo_hookean(), 1.768769888669576, 1.6679836498529308, (1.0,) * 3),
        )
    ],
    length=5.397338671613563,
    voltage=0.36296408441732747,
    inner_pressure=0.08247930022284859,
    closed_ends=True,
    axial_force=0.0,
)  # fmt: skip
