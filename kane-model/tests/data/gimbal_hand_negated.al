% gimbal_hand.al with every equation negated: -(Fr + Fr*) = 0.
ZERO[1] = Y - 2*(J1 + K1 - J2 - K2)*SIN(Q2)*COS(Q2)*U1*U2 - K1*SIN(Q2)*U2*U3 &
          + (I1 + J1*COS(Q2)^2 + J2*SIN(Q2)^2 + K1*COS(Q2)^2 + K2*SIN(Q2)^2)*U1' + K1*COS(Q2)*U3'
ZERO[2] = Z - (J2 + K2 - J1 - K1)*SIN(Q2)*COS(Q2)*U1^2 + K1*SIN(Q2)*U1*U3 + (J1 + K2)*U2'
ZERO[3] = -K1*SIN(Q2)*U1*U2 + K1*COS(Q2)*U1' + K1*U3'
