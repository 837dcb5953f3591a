// Compiles: it only shifts the file numbers so the library with the error is file 2.
float fine_too(float x) { return x; }
