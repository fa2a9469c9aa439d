// Constants more than one shader part needs.

const float kPi = 3.14159265358979;
