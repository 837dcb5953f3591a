// A library that uses an undeclared name on line 3 (Mesa reports this one with source 0).

float uses_undeclared(float x) { return x + not_declared_anywhere; }
