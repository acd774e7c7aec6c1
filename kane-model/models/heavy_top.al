% The heavy symmetric top of the EJS "Gyroscope" model (shared seed 000_45039c6968bab2b3.txt).
% A uniform solid ellipsoid rotor (semi-axes RR, RR, RR/5; axis 3 is the axle) with its centre at
% D along the axle from the fixed support O; gravity -G N3>. Orientation by Euler parameters
% (Autolev order: E1, E2, E3 the vector part, E4 the scalar), speeds the body-frame angular
% velocity components W1, W2, W3.
% The EJS text gives the axial moment as 4MR^2/5; the ellipsoid formula gives 2MR^2/5 for these
% semi-axes, and that is what SOLID_ELLIPSOID computes (an extension: Autolev has no shapes).
NEWTONIAN N
BODIES R
POINT O
CONSTANTS M, G, RR, D
VARIABLES E{4}', W{3}'
DIRCOS(N, R, EULER, E1, E2, E3, E4)
W_R_N> = W1*R1> + W2*R2> + W3*R3>
KINDIFFS(N, R, EULER, E1, E2, E3, E4)
V_O_N> = 0>
P_O_RO> = D*R3>
V2PTS(N, R, O, RO)
MASS R = M
INERTIA R, SOLID_ELLIPSOID(RR, RR, RR/5)
GRAVITY(-G*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, G = 1, RR = 1, D = 1
INPUT E1 = 0.5, E2 = 0, E3 = 0, E4 = 0.8660254037844386, W1 = 0, W2 = 0, W3 = 10
OUTPUT E1, E2, E3, E4, W1, W2, W3
