% Euler's equations for models/free_body.al solved for the rates, with W3' negated.
W1' = (I2 - I3)*W2*W3/I1
W2' = (I3 - I1)*W1*W3/I2
W3' = (I2 - I1)*W1*W2/I3
