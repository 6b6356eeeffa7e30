// sRGB transfer function (IEC 61966-2-1), applied once at the end of the frame.
vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// The same transfer function to within 0.25/255 (checked against it at 400,001 points of [0, 1];
// 1.6 % of 8-bit results round one step apart), for a shader that writes sRGB bytes itself. The
// curve part is a fit in c^(1/2), c^(1/4), c^(1/8) and c (the square-root series of "sRGB
// Approximations for HLSL", chilliant.blogspot.com, 2012): three square roots instead of the pow's
// log and exp, which cost more than llvmpipe's own sRGB store. On llvmpipe (98k grid, none,
// 1280x720, stop 66) GL's store cost 2.1-2.2 ms of the opaque pass; this encode saves ~1.3 of it.
vec3 linearToSrgbFast(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 s1 = sqrt(c), s2 = sqrt(s1), s3 = sqrt(s2);
    vec3 curve = 0.662002687 * s1 + 0.684122060 * s2 - 0.323583601 * s3 - 0.0225411470 * c;
    return mix(curve, c * 12.92, lessThan(c, vec3(0.0031308)));
}
