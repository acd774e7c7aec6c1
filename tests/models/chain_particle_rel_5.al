% The planar relative-angle chain, 5 particle links: written by tests/data/make_chain_fixtures.py
% (kane-model/benches/scaling/chain_model.py --links 5 --links-kind particle).
NEWTONIAN N
FRAMES F1, F2, F3, F4, F5
POINTS O
PARTICLES P1, P2, P3, P4, P5
CONSTANTS L{5}, M{5}, G
VARIABLES Q{5}', U{5}'
SIMPROT(N, F1, 3, Q1)
SIMPROT(F1, F2, 3, Q2)
SIMPROT(F2, F3, 3, Q3)
SIMPROT(F3, F4, 3, Q4)
SIMPROT(F4, F5, 3, Q5)
Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
Q5' = U5
V_O_N> = 0>
P_O_P1> = L1*F11>
P_P1_P2> = L2*F21>
P_P2_P3> = L3*F31>
P_P3_P4> = L4*F41>
P_P4_P5> = L5*F51>
V2PTS(N, F1, O, P1)
V2PTS(N, F2, P1, P2)
V2PTS(N, F3, P2, P3)
V2PTS(N, F4, P3, P4)
V2PTS(N, F5, P4, P5)
MASS P1 = M1, P2 = M2, P3 = M3, P4 = M4, P5 = M5
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
