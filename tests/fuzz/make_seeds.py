#!/usr/bin/env python3
"""Builds the seed corpora in tests/fuzz/seeds/<target>/ from the repository's own files
(tests/data, scenes/, shaders/) plus a few small hand-made files for formats the repository has
no sample of (GLB, PLY, TGA, BMP). Several files travel as one input, cut at `@@file NAME`
lines (see FuzzFiles.h). Run it again when tests/data changes; the output is committed."""
import base64, json, os, pathlib, shutil, struct

root = pathlib.Path(__file__).resolve().parents[2]
seeds = root / "tests/fuzz/seeds"
data = root / "tests/data"

def put(target, name, content):
    d = seeds / target
    d.mkdir(parents=True, exist_ok=True)
    (d / name).write_bytes(content if isinstance(content, bytes) else content.encode())

def bundle(main, *others):
    out = main
    for name, body in others:
        out += b"\n@@file " + name.encode() + b"\n" + body
    return out

shutil.rmtree(seeds, ignore_errors=True)
rd = lambda p: pathlib.Path(p).read_bytes()

# --- scenes: every scene of the repository, and one that carries its own model and texture.
for p in list(data.glob("*.json")) + list((root / "scenes").glob("*.json")):
    put("scene_file", p.name, rd(p))
box_obj = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/2 3/1\nf 1/1 3/2 4/1\n"
scene = {
    "name": "fuzz seed", "ambient": 0.1, "background": [0.2, 0.3, 0.4], "fog": {"start": 5, "end": 40},
    "technique": "cssm2",
    "camera": {"position": [4, 3, 6], "target": [0, 0, 0], "fov_deg": 50, "near": 0.1, "far": 100, "controller": "orbit"},
    "camera_path": {"position": [[0, 4, 3, 6], [2, -4, 3, 6], [4, 4, 3, 6]], "target": [[0, 0, 0, 0]]},
    "lights": [
        {"type": "directional", "direction": [-1, -2, -1], "color": [1, 1, 1], "intensity": 1,
         "shadow": {"resolution": 256, "bias": 0.001, "slope_bias": 1, "normal_offset": 0.01, "polygon_offset": [1, 1]}},
        {"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "angle_deg": 40, "near": 0.1, "range": 20},
        {"type": "point", "position": [1, 2, 1], "size": 0.2},
        {"type": "projector", "position": [0, 4, 4], "direction": [0, -1, -1], "image": "quadrants.png"}],
    "objects": [
        {"shape": "plane", "size": [20, 20]},
        {"shape": "box", "size": [1, 2, 1], "position": [0, 1, 0], "rotation_deg": [0, 30, 0],
         "material": {"diffuse": [0.1, 0.9, 0.1], "transmission": [0.1, 0.9, 0.1], "alpha": 0.5,
                      "texture": "quadrants.png", "double_sided": True, "shininess": 20, "alpha_cutoff": 0.1},
         "animation": {"position": [[0, 0, 1, 0], [1, 0, 2, 0]], "rotation_deg": [[0, 0, 0, 0], [1, 0, 90, 0]]}},
        {"shape": "sphere", "radius": 0.5, "cast_shadows": False, "visible": True, "animation": [[0, 1, 1, 1], [2, 2, 1, 1]]},
        {"model": "box.obj", "scale": [1, 1, 1], "name": "box"}]}
put("scene_file", "everything.json", bundle(json.dumps(scene, indent=1).encode(), ("box.obj", box_obj),
                                              ("quadrants.png", rd(data / "quadrants.png"))))

# --- OBJ with its MTL, and the repository's own OBJ files (the big ones cut to their first 16 KiB).
put("model_obj", "materials.obj", bundle(rd(data / "materials.obj"), ("materials.mtl", rd(data / "materials.mtl"))))
put("model_obj", "broken.obj", rd(data / "broken.obj"))
put("model_obj", "box.obj", box_obj)
put("model_obj", "teapot_head.obj", rd(root / "scenes/assets/teapot/teapot.obj")[:16384])
put("model_obj", "spot_head.obj", rd(root / "scenes/assets/spot/spot_triangulated.obj")[:16384])
put("model_obj", "groups.obj", b"mtllib m.mtl\no a\ng g1\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n"
    b"f 1//1 2//1 3//1\ns 1\nl 1 2\np 3\nf -3 -2 -1\n"
    b"\n@@file m.mtl\nnewmtl red\nKd 1 0 0\nKs 1 1 1\nNs 50\nd 0.5\nTf 0.2 0.2 0.8\nillum 4\nmap_Kd t.png\n"
    b"\n@@file t.png\n" + rd(data / "quadrants.png"))

# --- glTF (embedded buffers), and the same as GLB: JSON chunk + BIN chunk.
gltf = json.loads(rd(data / "materials.gltf"))
put("model_gltf", "materials.gltf", rd(data / "materials.gltf"))
put("model_gltf", "broken.gltf", rd(data / "broken.gltf"))
uri = gltf["buffers"][0]["uri"]
binary = base64.b64decode(uri.split(",", 1)[1])
glb = json.loads(json.dumps(gltf))
glb["buffers"] = [{"byteLength": len(binary)}]
js = json.dumps(glb, separators=(",", ":")).encode()
js += b" " * (-len(js) % 4)
binary += b"\0" * (-len(binary) % 4)
body = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(binary), b"BIN\0") + binary
put("model_glb", "materials.glb", struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)
ext = json.loads(json.dumps(gltf))
ext["buffers"] = [{"byteLength": len(base64.b64decode(uri.split(",", 1)[1])), "uri": "data.bin"}]
put("model_gltf", "external_buffer.gltf", bundle(json.dumps(ext).encode(), ("data.bin", base64.b64decode(uri.split(",", 1)[1]))))

# --- PLY, ASCII and binary, with colours.
put("model_ply", "ascii.ply", b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    b"property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face 2\n"
    b"property list uchar int vertex_indices\nend_header\n0 0 0 255 0 0\n1 0 0 0 255 0\n1 1 0 0 0 255\n"
    b"0 1 0 255 255 255\n3 0 1 2\n3 0 2 3\n")
verts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 1)]
put("model_ply", "binary.ply", b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
    b"property float y\nproperty float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
    + b"".join(struct.pack("<3f", *v) for v in verts) + struct.pack("<B3i", 3, 0, 1, 2) + struct.pack("<B3i", 3, 0, 2, 3))

# --- images: the repository's PNGs, a JPEG from Debian's docs, and hand-made TGA and BMP.
put("image", "quadrants.png", rd(data / "quadrants.png"))
put("image", "spot_texture.png", rd(root / "scenes/assets/spot/spot_texture.png"))
jpg = pathlib.Path("/usr/share/doc/nodejs/thin-white-stripe.jpg")
if jpg.exists():
    put("image", "stripe.jpg", rd(jpg))
put("image", "rgb.tga", struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, 2, 2, 24, 0) + bytes([0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255]))
pixels = bytes([0, 0, 255, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 0])  # 2x2, 24-bit, rows padded to 4
put("image", "rgb.bmp", b"BM" + struct.pack("<IHHI", 54 + len(pixels), 0, 0, 54) +
    struct.pack("<IiiHHIIiiII", 40, 2, 2, 1, 24, 0, len(pixels), 2835, 2835, 0, 0) + pixels)

# --- GLSL: includes, a nested chain, a cycle, an override slot.
put("shader_include", "chain.glsl", b'#version 450 core\n#include "a.glsl"\n#include "slot.glsl"\nvoid main() {}\n'
    b'\n@@file slot.glsl\nfloat slot() { return 1.0; }\n'
    b'\n@@file a.glsl\n#include "b.glsl"\nfloat a() { return b(); }\n'
    b'\n@@file b.glsl\nfloat b() { return 2.0; }\n')
put("shader_include", "cycle.glsl", b'#version 450 core\n#include "x.glsl"\n\n@@file x.glsl\n#include "y.glsl"\n'
    b'\n@@file y.glsl\n#include "x.glsl"\n#include "main.glsl"\n')
put("shader_include", "missing.glsl", b'#version 450 core\n  #  include   "nowhere.glsl"  \n')
# (the renderer's own shaders/ are a seed folder of their own, see tests/fuzz/CMakeLists.txt)
print("seeds:", {d.name: len(list(d.iterdir())) for d in sorted(seeds.iterdir())})

# --- libFuzzer dictionaries: the keys and keywords each format is made of.
def write_dict(name, entries):
    def esc(e):
        return "".join(c if 32 <= ord(c) < 127 and c not in '\\"' else
                       ("\\" + c if c in '\\"' else "\\x%02x" % ord(c)) for c in e)
    d = root / "tests/fuzz/dict"
    d.mkdir(exist_ok=True)
    with open(d / name, "w") as f:
        f.write("# libFuzzer dictionary, written by tests/fuzz/make_seeds.py\n")
        for i, e in enumerate(entries):
            f.write(f'kw{i}="{esc(e)}"\n')

scene_keys = """name description camera camera_path ambient background fog lights objects technique position target up
fov_deg near far controller fly trackball orbit start end type color intensity direction angle_deg image shadow size
range directional spot point projector enabled resolution bias slope_bias normal_offset polygon_offset diffuse
specular shininess texture alpha transmission alpha_cutoff double_sided model shape radius rotation_deg scale
material animation cast_shadows visible plane box sphere""".split()
json_tokens = ["{", "}", "[", "]", ":", ",", "true", "false", "null", "0", "-1", "1e308", "-1e309", "1e-320", "65536",
               "16384", "0.5", '"../"', '"/dev/zero"', '"\\u0000"', '"\\ud800"']
write_dict("scene.dict", ['"%s"' % k for k in scene_keys] + json_tokens + ["\n@@file box.obj\n", "\n@@file t.png\n"])
gltf_keys = """asset version generator scene scenes nodes mesh meshes children matrix translation rotation scale buffers
buffer bufferViews bufferView byteOffset byteLength byteStride target uri accessors componentType count type min max
normalized sparse indices values SCALAR VEC2 VEC3 VEC4 MAT4 materials pbrMetallicRoughness baseColorFactor
baseColorTexture metallicFactor roughnessFactor alphaMode alphaCutoff OPAQUE MASK BLEND doubleSided textures images
samplers source sampler index texCoord primitives attributes POSITION NORMAL TEXCOORD_0 COLOR_0 mode extensions
extensionsUsed extensionsRequired KHR_materials_transmission transmissionFactor KHR_materials_volume attenuationColor
attenuationDistance thicknessFactor skins animations cameras mimeType""".split()
write_dict("gltf.dict", ['"%s"' % k for k in gltf_keys] + json_tokens +
           ["glTF", "JSON", "BIN\0", "5126", "5123", "5125", "5121", "data:application/octet-stream;base64,"])
write_dict("obj.dict", ["v ", "vt ", "vn ", "vp ", "f ", "l ", "p ", "o ", "g ", "s ", "usemtl ", "mtllib ", "newmtl ",
                        "Kd ", "Ka ", "Ks ", "Ke ", "Ns ", "Ni ", "d ", "Tr ", "Tf ", "illum ", "map_Kd ", "map_d ", "bump ",
                        "/", "//", "-1", "1e38", "nan", "inf", "\n@@file materials.mtl\n", "\n@@file t.png\n"])
write_dict("ply.dict", ["ply", "format ascii 1.0", "format binary_little_endian 1.0", "format binary_big_endian 1.0",
                        "element", "vertex", "face", "property", "float", "double", "uchar", "int", "uint", "list",
                        "vertex_indices", "x", "y", "z", "nx", "red", "green", "blue", "alpha", "end_header", "comment"])
write_dict("glsl.dict", ['#include "', "#version 450 core", "#line ", "#define ", "\n@@file ", "slot.glsl", "main.glsl",
                         "a.glsl", "../", "/", "0:12(5): error", "4294967296(1) : error"])
