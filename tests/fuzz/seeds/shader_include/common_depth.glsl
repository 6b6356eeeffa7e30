// Distance along a perspective light's axis from its window depth z (GL projection, near n,
// far f): the inverse of f/(f-n) - f n / ((f-n) d). Shared by every pass that linearises depth.
float perspectiveViewDepth(float z, float n, float f) { return n * f / (f - z * (f - n)); }

// The same distance mapped to [0, 1] between the planes.
float perspectiveLinearDepth(float z, float n, float f) { return (perspectiveViewDepth(z, n, f) - n) / (f - n); }
