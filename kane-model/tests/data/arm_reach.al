% The joint angles of a planar two-link arm whose tip reaches (X, Y): solved by CODE NONLINEAR
% from the starting angles below (elbow up).
CONSTANTS L1, L2, X, Y
VARIABLES Q1, Q2
EQN[1] = L1*COS(Q1) + L2*COS(Q1 + Q2) - X
EQN[2] = L1*SIN(Q1) + L2*SIN(Q1 + Q2) - Y
INPUT L1 = 0.5, L2 = 0.4, X = 0.6, Y = 0.3
INPUT Q1 = 20 DEG, Q2 = 60 DEG
CODE NONLINEAR(EQN, Q1, Q2) reach.c
