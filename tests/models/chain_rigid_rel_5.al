% The planar relative-angle chain, 5 rigid links: written by tests/data/make_chain_fixtures.py
% (kane-model/benches/scaling/chain_model.py --links 5 --links-kind rigid).
NEWTONIAN N
BODIES B1, B2, B3, B4, B5
POINTS O, J1, J2, J3, J4
CONSTANTS L{5}, M{5}, I{5}, G
VARIABLES Q{5}', U{5}'
SIMPROT(N, B1, 3, Q1)
SIMPROT(B1, B2, 3, Q2)
SIMPROT(B2, B3, 3, Q3)
SIMPROT(B3, B4, 3, Q4)
SIMPROT(B4, B5, 3, Q5)
Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
Q5' = U5
V_O_N> = 0>
P_O_B1O> = L1/2*B11>
P_O_J1> = L1*B11>
P_J1_B2O> = L2/2*B21>
P_J1_J2> = L2*B21>
P_J2_B3O> = L3/2*B31>
P_J2_J3> = L3*B31>
P_J3_B4O> = L4/2*B41>
P_J3_J4> = L4*B41>
P_J4_B5O> = L5/2*B51>
V2PTS(N, B1, O, B1O)
V2PTS(N, B1, O, J1)
V2PTS(N, B2, J1, B2O)
V2PTS(N, B2, J1, J2)
V2PTS(N, B3, J2, B3O)
V2PTS(N, B3, J2, J3)
V2PTS(N, B4, J3, B4O)
V2PTS(N, B4, J3, J4)
V2PTS(N, B5, J4, B5O)
MASS B1 = M1, B2 = M2, B3 = M3, B4 = M4, B5 = M5
INERTIA B1, 0, I1, I1
INERTIA B2, 0, I2, I2
INERTIA B3, 0, I3, I3
INERTIA B4, 0, I4, I4
INERTIA B5, 0, I5, I5
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
