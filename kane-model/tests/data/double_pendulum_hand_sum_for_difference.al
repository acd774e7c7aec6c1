% Fr + Fr* written with angle differences; ZERO[2] has sin(Q1 + Q2) where sin(Q1 - Q2) belongs
% (and the opposite sign).
ZERO[1] = -(M1+M2)*L1^2*U1' - M2*L1*L2*COS(Q1-Q2)*U2' - M2*L1*L2*SIN(Q1-Q2)*U2^2 - (M1+M2)*G*L1*SIN(Q1)
ZERO[2] = -M2*L1*L2*COS(Q1-Q2)*U1' - M2*L2^2*U2' + M2*L1*L2*SIN(Q1+Q2)*U1^2 - M2*G*L2*SIN(Q2)
