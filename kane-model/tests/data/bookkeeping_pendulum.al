% A compound pendulum written as research Autolev files are: a unit system, session
% settings, `;` terminators, several statements on a line and compound unit tags.
UNITSYSTEM G, CM, SEC
AUTOZ ON
AUTORHS OFF
AUTOEPSILON 1.0E-14
BEEPSOUND OFF
FACTORING ON
OVERWRITE ALL
NEWTONIAN N;
BODIES B;
POINTS O;
CONSTANTS M, L, G, IZZ;
VARIABLES Q', U'
SIMPROT(N, B, 3, Q);  Q' = U;
P_O_BO> = L*B1>;  V_O_N> = 0>;  V2PTS(N, B, O, BO);
MASS B = M
INERTIA B, 0, IZZ, IZZ
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR();
KANE();
PAUSE
INPUT M = 2 KG, L = 0.5 M, G = 9.81 M/S^2, IZZ = 0.04 KG.M^2
INPUT Q = 30 DEG, U = 60 RPM
OUTPUT Q RAD, U RAD/SEC, L CM
ENCODE ZERO
SAVE bookkeeping_pendulum.all
