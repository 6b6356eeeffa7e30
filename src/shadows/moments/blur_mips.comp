#version 450 core
// The moments' pre-filter and their first mip levels in one compute pass (`compute_blur`), after
// Peters & Klein's (HPG 2017) compute resolve with a shared-memory blur. Each group of 16 x 16
// invocations makes one 16 x 16 tile of level 0 and the tile's texels of levels 1-4 beneath it:
// - the unblurred moments around the tile (18 x 18, edges clamped) are fetched once each into
//   shared memory, where the 3 x 3 kernel reads them: one texelFetch a texel instead of
//   blur_bilinear.frag's four bilinear fetches;
// - each level below is the mean of its 2 x 2 texels of the level above (downsample.frag's box,
//   what glGenerateMipmap computes), taken from shared memory, not from the map again.
// The kernel is separable, (left, centre, right) on each axis: the radius-1 Gaussian
// (w, 1 - 2w, w) of blur_bilinear.frag, or blur_box.frag's 2 x 2 box (0, 1/2, 1/2).
// Texels outside uReached keep what level 0 holds (cleared to the far plane's moments, or kept from
// a frame before): read back, not blurred, so that the levels below average what level 0 holds.
// Each level is written only inside its own rectangle (uLevelRect): the rest is the caller's.
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0) uniform sampler2D uRaw;  // the casters' unblurred moments, read texel by texel
layout(binding = 0, MOMENT_IMAGE_FORMAT) uniform image2D uLevel0;
layout(binding = 1, MOMENT_IMAGE_FORMAT) uniform writeonly image2D uLevel1;
layout(binding = 2, MOMENT_IMAGE_FORMAT) uniform writeonly image2D uLevel2;
layout(binding = 3, MOMENT_IMAGE_FORMAT) uniform writeonly image2D uLevel3;
layout(binding = 4, MOMENT_IMAGE_FORMAT) uniform writeonly image2D uLevel4;

uniform ivec2 uTileOrigin;     // level-0 texel of group (0, 0)'s corner, a multiple of 16
uniform ivec4 uLevelRect[5];   // per level: texels [x0, x1) x [y0, y1) this pass writes; level 0's: the blurred ones
uniform int uLevels;           // levels written, 1-5
uniform vec3 uWeights;         // the kernel on each axis: texels p - 1, p, p + 1

const int kTile = 16;
shared vec4 sRaw[kTile + 2][kTile + 2];
shared vec4 sLevel[kTile][kTile];

bool inside(ivec2 p, ivec4 rect) { return all(greaterThanEqual(p, rect.xy)) && all(lessThan(p, rect.zw)); }

void store(int level, ivec2 p, vec4 v) {
    if (level == 1) imageStore(uLevel1, p, v);
    else if (level == 2) imageStore(uLevel2, p, v);
    else if (level == 3) imageStore(uLevel3, p, v);
    else imageStore(uLevel4, p, v);
}

void main() {
    const ivec2 size = textureSize(uRaw, 0);
    const ivec2 corner = uTileOrigin + ivec2(gl_WorkGroupID.xy) * kTile;
    for (int i = int(gl_LocalInvocationIndex); i < (kTile + 2) * (kTile + 2); i += kTile * kTile) {
        ivec2 q = ivec2(i % (kTile + 2), i / (kTile + 2));
        sRaw[q.y][q.x] = texelFetch(uRaw, clamp(corner + q - 1, ivec2(0), size - 1), 0);
    }
    barrier();

    const ivec2 local = ivec2(gl_LocalInvocationID.xy), p = corner + local;
    vec4 v = vec4(0.0);
    if (inside(p, uLevelRect[0])) {
        for (int y = 0; y < 3; ++y) {
            vec4 row = uWeights.x * sRaw[local.y + y][local.x] + uWeights.y * sRaw[local.y + y][local.x + 1] +
                       uWeights.z * sRaw[local.y + y][local.x + 2];
            v += uWeights[y] * row;
        }
        imageStore(uLevel0, p, v);
    } else if (uLevels > 1 && all(lessThan(p, size))) {
        v = imageLoad(uLevel0, p);
    }
    sLevel[local.y][local.x] = v;
    barrier();

    for (int level = 1; level < 5; ++level) {  // uniform control flow: every invocation meets each barrier
        const int n = kTile >> level;
        const bool mine = all(lessThan(local, ivec2(n)));
        vec4 mean = vec4(0.0);
        if (mine) {
            ivec2 c = 2 * local;
            mean = 0.25 * (sLevel[c.y][c.x] + sLevel[c.y][c.x + 1] + sLevel[c.y + 1][c.x] + sLevel[c.y + 1][c.x + 1]);
        }
        barrier();
        if (mine) {
            sLevel[local.y][local.x] = mean;
            const ivec2 q = (corner >> level) + local;
            if (level < uLevels && inside(q, uLevelRect[level])) store(level, q, mean);
        }
        barrier();
    }
}
