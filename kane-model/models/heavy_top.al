% The heavy symmetric top of the EJS "Gyroscope" model (shared seed 000_45039c6968bab2b3.txt).
% A uniform solid ellipsoid rotor (semi-axes RR, RR, RR/5; axis 3 is the axle) with its centre at
% D along the axle from the fixed support O; gravity -G N3>. Orientation by Euler parameters
% (Autolev order: E1, E2, E3 the vector part, E4 the scalar), speeds the body-frame angular
% velocity components W1, W2, W3.
% The EJS text gives the axial moment as 4MR^2/5; the ellipsoid formula gives 2MR^2/5 for these
% semi-axes. Both are offered: the axial moment is AXIAL*M*RR^2, AXIAL = 2/5 (the physics) by
% default, 4/5 for the EJS text. The transverse moment (RR^2 + (RR/5)^2)/5 = 26/125 M RR^2 agrees
% with both.
NEWTONIAN N
BODIES R
POINT O
CONSTANTS M, G, RR, D, AXIAL
VARIABLES E{4}', W{3}'
DIRCOS(N, R, EULER, E1, E2, E3, E4)
W_R_N> = W1*R1> + W2*R2> + W3*R3>
KINDIFFS(N, R, EULER, E1, E2, E3, E4)
V_O_N> = 0>
P_O_RO> = D*R3>
V2PTS(N, R, O, RO)
MASS R = M
INERTIA R, 26/125*M*RR^2, 26/125*M*RR^2, AXIAL*M*RR^2
GRAVITY(-G*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, G = 1, RR = 1, D = 1, AXIAL = 0.4
INPUT E1 = 0.5, E2 = 0, E3 = 0, E4 = 0.8660254037844386, W1 = 0, W2 = 0, W3 = 10
OUTPUT E1, E2, E3, E4, W1, W2, W3
% In space axes (N): the axle's direction, the angular momentum about the support, the angular
% velocity, and the gravity torque about the support.
AXLE> = R3>
L> = MOMENTUM(ANGULAR, O)
OMEGA> = W_R_N>
TORQUE> = CROSS(P_O_RO>, -M*G*N3>)
% Elevations above the horizontal: of the axle, and of L (ATAN2 is defined, zero, when L = 0).
ELEVATION = ATAN2(DOT(R3>, N3>), SQRT(DOT(R3>, N1>)^2 + DOT(R3>, N2>)^2))
L_ELEVATION = ATAN2(DOT(L>, N3>), SQRT(DOT(L>, N1>)^2 + DOT(L>, N2>)^2))
% Total energy (zero of potential at the support), and the conserved L_z and L_3 (along the axle).
ENERGY = KE() + M*G*D*DOT(R3>, N3>)
LZ = DOT(L>, N3>)
L3 = DOT(L>, R3>)
UNITS W1 = RAD/SEC, W2 = RAD/SEC, W3 = RAD/SEC, ELEVATION = DEG, L_ELEVATION = DEG
OUTPUT AXLE>, L>, OMEGA>, TORQUE>, ELEVATION, L_ELEVATION, ENERGY, LZ, L3
