% gimbal_hand_velocity.al without the U3 term of the D3> component.
V_P_A> = L*(U2*SIN(Q3) - U1*SIN(Q2)*COS(Q3))*D2> + L*U1*COS(Q2)*D3>
