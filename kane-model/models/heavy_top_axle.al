% The heavy symmetric top of heavy_top.al, spin-aware: the orientation integrated is that of the
% axle frame A, which turns with the axle but not with the spin (its angular velocity has no
% component along the axle, A3>); the rotor R turns relative to A by the spin angle PSI about A3>.
% So the Euler parameters E1..E4 (of A) and the rates W1, W2 (of A, along A1>, A2>) move at the
% pace of the nutation and the precession, never at the spin's; W3 is the rotor's whole rate
% about the axle, and PSI' = W3.
% Exact, not an approximation, because the rotor is axisymmetric about A3> (equal transverse
% moments) and the loads have no moment about the axle that depends on PSI: then no equation
% reads PSI (the generated code shows it; kane-model's test spin_aware.rs checks it), PSI is
% cyclic, and the motion of the axle is that of heavy_top.al. Unequal transverse moments bring
% sin(PSI), cos(PSI) back into the equations and the spin sets the step again.
% At PSI = 0 the rotor's frame is A, so initial values are those of heavy_top.al.
NEWTONIAN N
FRAMES A
BODIES R
POINT O
CONSTANTS M, G, RR, D, AXIAL
VARIABLES E{4}', W{3}', PSI'
DIRCOS(N, A, EULER, E1, E2, E3, E4)
W_A_N> = W1*A1> + W2*A2>
KINDIFFS(N, A, EULER, E1, E2, E3, E4)
SIMPROT(A, R, 3, PSI)
PSI' = W3
V_O_N> = 0>
P_O_RO> = D*A3>
V2PTS(N, R, O, RO)
MASS R = M
INERTIA R, 26/125*M*RR^2, 26/125*M*RR^2, AXIAL*M*RR^2
GRAVITY(-G*N3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, G = 1, RR = 1, D = 1, AXIAL = 0.4
INPUT E1 = 0.5, E2 = 0, E3 = 0, E4 = 0.8660254037844386, W1 = 0, W2 = 0, W3 = 10, PSI = 0
OUTPUT E1, E2, E3, E4, W1, W2, W3
% As in heavy_top.al, in space axes: the axle, L about the support, the rotor's angular velocity,
% the gravity torque; the elevations, the energy and the conserved L_z and L_3.
AXLE> = A3>
L> = MOMENTUM(ANGULAR, O)
OMEGA> = W_R_N>
TORQUE> = CROSS(P_O_RO>, -M*G*N3>)
ELEVATION = ATAN2(DOT(A3>, N3>), SQRT(DOT(A3>, N1>)^2 + DOT(A3>, N2>)^2))
L_ELEVATION = ATAN2(DOT(L>, N3>), SQRT(DOT(L>, N1>)^2 + DOT(L>, N2>)^2))
ENERGY = KE() + M*G*D*DOT(A3>, N3>)
LZ = DOT(L>, N3>)
L3 = DOT(L>, A3>)
UNITS W1 = RAD/SEC, W2 = RAD/SEC, W3 = RAD/SEC, PSI = RAD, ELEVATION = DEG, L_ELEVATION = DEG
OUTPUT AXLE>, L>, OMEGA>, TORQUE>, ELEVATION, L_ELEVATION, ENERGY, LZ, L3
