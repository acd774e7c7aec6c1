% The velocity of P in A by hand, in D's unit vectors: w_D = (-U2*COS(Q3) - U1*SIN(Q2)*SIN(Q3),
% -U1*COS(Q2) - U3, U2*SIN(Q3) - U1*SIN(Q2)*COS(Q3)) in D, and V = w_D x L*D1>.
V_P_A> = L*(U2*SIN(Q3) - U1*SIN(Q2)*COS(Q3))*D2> + L*(U1*COS(Q2) + U3)*D3>
K1 = M3*L^2/2
% B turns about -A2> at the rate U1 (SIMPROT(A, B, -2, Q1)); compared in A's unit vectors.
W_B_A> = -U1*A2>
