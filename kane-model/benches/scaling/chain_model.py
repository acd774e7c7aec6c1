"""Write an n-link chain as a model file in our Autolev dialect (to standard output).

    python3 chain_model.py --links N [--angles {relative,absolute}] [--plane {planar,spatial}]
                           [--links-kind {particle,rigid}] [--cart] [--inputs]

Defaults: relative angles, planar, point masses. The output is one model file: check it with
`kane check FILE`, derive it with `kane eoms FILE`, generate it with `kane gen FILE`. `--inputs`
appends INPUT lines (unit lengths and masses, G = 9.81, slender-rod inertias, small angles, zero
speeds) so that `kane eval FILE` runs without --set.

The chains (i = 1..n; a fixed pivot O at the origin of the Newtonian frame N; gravity -G*N2>;
kinematics Qi' = Ui):

* Joint axis a(i) and link direction d(i): planar, a(i) = 3 and d(i) = 1 for every link (the
  chain moves in the N1-N2 plane). Spatial, a(i) = 3 for odd i and 1 for even i, d(i) = 2: link
  i points along its frame's axis 2, and the joints alternate between axis 3 and axis 1 (so
  every joint is a hinge, but successive hinges are perpendicular and the chain leaves the
  plane).
* Angles: relative, frame i is rotated from frame i-1 (N for i = 1) by Qi about axis a(i),
  `SIMPROT(F(i-1), Fi, a(i), Qi)`. Absolute, frame i is rotated from N by Qi about N's axis
  a(i), `SIMPROT(N, Fi, a(i), Qi)` (planar: Qi is link i's angle from N1>).
* Links: particle, frames F1..Fn and particles P1..Pn of masses Mi at the links' far ends,
  P_P(i-1)_Pi> = Li*Fi{d(i)}> with P0 = O (massless rods between point masses; the planar
  relative form is exactly the issue's reviewer generator). Rigid, bodies B1..Bn (the frames
  are B1..Bn) pinned end to end, SD/FAST's benchmark form: joint points J1..J(n-1) with J0 = O,
  P_J(i-1)_Ji> = Li*Bi{d(i)}>, the mass centre BiO at mid-link, P_J(i-1)_BiO> = Li/2*Bi{d(i)}>,
  mass Mi, central inertia a rod's: planar `INERTIA Bi, 0, Ii, Ii` (slender, along axis 1;
  only the moment Ii about the joint axis 3 acts, and the zero axial moment keeps the inertia
  physical, so `kane check` has no warning), spatial `INERTIA Bi, Ii, Ki, Ii` (transverse Ii,
  axial Ki about axis 2).

With `--cart`, the pivot O is a cart C (a particle of mass MC) sliding along N1> by X, with
`X' = UX` and `V_O_N> = UX*N1>`: the pendulum on a cart.

Velocities are by V2PTS from the link's joint (both points are fixed in the link's frame).
The SymPy side of the same chains is sympy_chain.py (same names, signs and mass centres).
"""
import argparse
import sys


def chain_model(n, angles="relative", plane="planar", kind="particle", inputs=False, cart=False):
    """The model file text of the chain, one statement a line."""
    assert n >= 1
    rigid = kind == "rigid"
    spatial = plane == "spatial"
    axis = [None] + [(3 if i % 2 == 1 else 1) if spatial else 3 for i in range(1, n + 1)]
    d = 2 if spatial else 1
    F = [None] + [f"{'B' if rigid else 'F'}{i}" for i in range(1, n + 1)]

    def parent(i):
        return "N" if (i == 1 or angles == "absolute") else F[i - 1]

    out = ["NEWTONIAN N"]
    if rigid:
        out.append("BODIES " + ", ".join(F[1:]))
        out.append("POINTS " + ", ".join(["O"] + [f"J{i}" for i in range(1, n)]))
        consts = f"CONSTANTS L{{{n}}}, M{{{n}}}, I{{{n}}}" + (f", K{{{n}}}" if spatial else "") + ", G"
        out.append(consts)
    else:
        out += ["FRAMES " + ", ".join(F[1:]), "POINTS O",
                "PARTICLES " + ", ".join(f"P{i}" for i in range(1, n + 1)),
                f"CONSTANTS L{{{n}}}, M{{{n}}}, G"]
    if cart:
        out += ["PARTICLES C", "CONSTANTS MC"]
    out.append(f"VARIABLES Q{{{n}}}', U{{{n}}}'" + (", X', UX'" if cart else ""))
    out += [f"SIMPROT({parent(i)}, {F[i]}, {axis[i]}, Q{i})" for i in range(1, n + 1)]
    out += [f"Q{i}' = U{i}" for i in range(1, n + 1)]
    if cart:
        out += ["X' = UX", "V_O_N> = UX*N1>", "V_C_N> = UX*N1>", "MASS C = MC"]
    else:
        out.append("V_O_N> = 0>")
    if rigid:
        J = ["O"] + [f"J{i}" for i in range(1, n)]
        for i in range(1, n + 1):
            out.append(f"P_{J[i - 1]}_{F[i]}O> = L{i}/2*{F[i]}{d}>")
            if i < n:
                out.append(f"P_{J[i - 1]}_{J[i]}> = L{i}*{F[i]}{d}>")
        for i in range(1, n + 1):
            out.append(f"V2PTS(N, {F[i]}, {J[i - 1]}, {F[i]}O)")
            if i < n:
                out.append(f"V2PTS(N, {F[i]}, {J[i - 1]}, {J[i]})")
        out.append("MASS " + ", ".join(f"{F[i]} = M{i}" for i in range(1, n + 1)))
        for i in range(1, n + 1):
            out.append(f"INERTIA {F[i]}, I{i}, K{i}, I{i}" if spatial else f"INERTIA {F[i]}, 0, I{i}, I{i}")
    else:
        out.append(f"P_O_P1> = L1*{F[1]}{d}>")
        out += [f"P_P{i - 1}_P{i}> = L{i}*{F[i]}{d}>" for i in range(2, n + 1)]
        out.append(f"V2PTS(N, {F[1]}, O, P1)")
        out += [f"V2PTS(N, {F[i]}, P{i - 1}, P{i})" for i in range(2, n + 1)]
        out.append("MASS " + ", ".join(f"P{i} = M{i}" for i in range(1, n + 1)))
    out += ["GRAVITY(-G*N2>)", "ZERO = FR() + FRSTAR()", "KANE()"]
    if inputs:
        vals = [f"L{i} = 1" for i in range(1, n + 1)] + [f"M{i} = 1" for i in range(1, n + 1)]
        if rigid:
            vals += [f"I{i} = 0.08333333333333333" for i in range(1, n + 1)]
            if spatial:
                vals += [f"K{i} = 0.001" for i in range(1, n + 1)]
        vals.append("G = 9.81")
        if cart:
            vals.append("MC = 1")
        out.append("INPUT " + ", ".join(vals))
        out.append("INPUT " + ", ".join([f"Q{i} = 0.1" for i in range(1, n + 1)]
                                        + [f"U{i} = 0" for i in range(1, n + 1)]
                                        + (["X = 0", "UX = 0"] if cart else [])))
    return "\n".join(out) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--links", type=int, required=True, help="number of links n >= 1")
    ap.add_argument("--angles", choices=["relative", "absolute"], default="relative")
    ap.add_argument("--plane", choices=["planar", "spatial"], default="planar")
    ap.add_argument("--links-kind", choices=["particle", "rigid"], default="particle")
    ap.add_argument("--cart", action="store_true", help="pivot on a cart sliding along N1>")
    ap.add_argument("--inputs", action="store_true", help="append INPUT lines")
    a = ap.parse_args(argv)
    sys.stdout.write(chain_model(a.links, a.angles, a.plane, a.links_kind, a.inputs, a.cart))


if __name__ == "__main__":
    main()
