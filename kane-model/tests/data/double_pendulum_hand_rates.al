% The textbook's rates of the double pendulum, as SymPy or a hand derivation writes them
% (angles from the downward vertical, differences and double angles of Q1 and Q2).
U1' = (-G*(2*M1+M2)*SIN(Q1) - M2*G*SIN(Q1-2*Q2) - 2*SIN(Q1-Q2)*M2*(U2^2*L2 + U1^2*L1*COS(Q1-Q2)))/(L1*(2*M1+M2-M2*COS(2*Q1-2*Q2)))
U2' = (2*SIN(Q1-Q2)*(U1^2*L1*(M1+M2) + G*(M1+M2)*COS(Q1) + U2^2*L2*M2*COS(Q1-Q2)))/(L2*(2*M1+M2-M2*COS(2*Q1-2*Q2)))
