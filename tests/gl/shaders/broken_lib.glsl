// A library with a syntax error on line 4.
float fine(float x) { return x; }

float broken(float x) { return x +; }
