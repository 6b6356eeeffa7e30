#!/usr/bin/env python3
"""Writes seed 002's three demo scenes and seed 000's coloured-glass scene into scenes/.

    scripts/make_demo_scenes.py        # rewrites scenes/{park,construction,street,glass}.json

The models are Sweet Home 3D furniture from Debian's sweethome3d-furniture package, copied into
scenes/assets/sh3d/ (licences in scenes/assets/README.md). Sweet Home 3D scales every model to
its catalogue size; CATALOGUE below holds those sizes (width x depth x height, cm, from the
package's PluginFurnitureCatalog.properties) and place() reproduces that scaling from the OBJ's
own bounds, so each model stands on the ground at its real size, centred where it is placed.
"""
import json
import math
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
ASSETS = os.path.join(ROOT, "scenes", "assets", "sh3d")

# model path under assets/sh3d -> catalogue width (x), depth (z), height (y) in cm
CATALOGUE = {
    "katorlegaz/bench/bench.obj": (118.2, 45.2, 45.0),
    "katorlegaz/classic-lamppost/classic-lamppost.obj": (30.0, 30.0, 250.0),
    "katorlegaz/park-light/park-light.obj": (61.4, 56.4, 300.0),
    "katorlegaz/park-trashcan/park-trashcan.obj": (79.0, 79.0, 85.8),
    "scopia/cypress/cypress.obj": (132.2, 134.2, 560.0),
    "scopia/cone/cone.obj": (37.9, 37.9, 70.0),
    "scopia/step-ladder-metal/step-ladder-metal.obj": (57.8, 75.9, 180.0),
    "scopia/wood_logs/wood_logs.obj": (40.3, 69.9, 31.8),
    "scopia/table-on-trestles/table-on-trestles.obj": (160.0, 66.4, 76.1),
    "scopia/smart-car/smart-car.obj": (170.8, 252.8, 154.6),
    "scopia/peugeot-308/peugeot-308.obj": (210.0, 444.0, 138.9),
    "blendswap-cc-0/pallet/pallet.obj": (120.0, 120.4, 12.0),
    "blendswap-cc-0/wheelbarrow/wheelbarrow.obj": (166.3, 59.8, 56.7),
    "blendswap-cc-0/pedestrianRailing1/pedestrianRailing1.obj": (208.1, 4.8, 103.9),
    "blendswap-cc-0/crate/crate.obj": (60.0, 58.9, 59.4),
    "blendswap-cc-0/barrel/barrel.obj": (81.5, 81.5, 89.7),
}


def obj_bounds(path):
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    with open(path, errors="ignore") as f:
        for line in f:
            if line.startswith("v "):
                v = [float(x) for x in line.split()[1:4]]
                lo = [min(a, b) for a, b in zip(lo, v)]
                hi = [max(a, b) for a, b in zip(hi, v)]
    return lo, hi


BOUNDS = {m: obj_bounds(os.path.join(ASSETS, m)) for m in CATALOGUE}


def r(x):
    return round(x, 4)


def place(model, x, z, yaw_deg=0.0, name=None, region=None, y=0.0):
    """The object that stands `model` on y at (x, z), turned by yaw_deg about the vertical."""
    lo, hi = BOUNDS[model]
    w, d, h = CATALOGUE[model]
    scale = [w / 100 / (hi[0] - lo[0]), h / 100 / (hi[1] - lo[1]), d / 100 / (hi[2] - lo[2])]
    # The model's bottom centre, scaled, then turned: the object's position puts it at (x, y, z).
    c = [(lo[0] + hi[0]) / 2 * scale[0], lo[1] * scale[1], (lo[2] + hi[2]) / 2 * scale[2]]
    a = math.radians(yaw_deg)
    cx = math.cos(a) * c[0] + math.sin(a) * c[2]
    cz = -math.sin(a) * c[0] + math.cos(a) * c[2]
    o = {"name": name or model.split("/")[1], "model": "assets/sh3d/" + model,
         "position": [r(x - cx), r(y - c[1]), r(z - cz)], "scale": [r(s) for s in scale]}
    if yaw_deg:
        o["rotation_deg"] = [0, yaw_deg, 0]
    if region:
        o["region"] = region
    return o


def box(name, size, position, diffuse, region=None, rotation=None):
    o = {"name": name, "shape": "box", "size": [r(s) for s in size], "position": [r(p) for p in position],
         "material": {"diffuse": diffuse}}
    if rotation:
        o["rotation_deg"] = rotation
    if region:
        o["region"] = region
    return o


def plane(name, size, position, diffuse, region=None):
    o = {"name": name, "shape": "plane", "size": size, "position": position, "material": {"diffuse": diffuse}}
    if region:
        o["region"] = region
    return o


def orbit(centre, radius, height, seconds, steps=8):
    keys = []
    for i in range(steps + 1):
        a = 2 * math.pi * i / steps
        keys.append([r(seconds * i / steps), r(centre[0] + radius * math.cos(a)), height, r(centre[2] + radius * math.sin(a))])
    return keys


def park():
    objects = [plane("lawn", [30, 30], [0, 0, 0], [0.32, 0.5, 0.22]),
               plane("gravel path", [3, 30], [0, 0.01, 0], [0.72, 0.68, 0.6])]
    objects += [place("katorlegaz/bench/bench.obj", -2.2, 0, 90, "bench"),
                place("katorlegaz/bench/bench.obj", -2.2, 4, 90, "bench 2"),
                place("katorlegaz/bench/bench.obj", 2.2, -3, -90, "bench 3"),
                place("katorlegaz/park-trashcan/park-trashcan.obj", -2.3, 1.6, 0, "trash can"),
                place("katorlegaz/park-light/park-light.obj", 1.9, 1.5, 0, "park light"),
                place("katorlegaz/park-light/park-light.obj", -1.9, -5, 0, "park light 2"),
                place("scopia/cypress/cypress.obj", -5, -2, 0, "cypress"),
                place("scopia/cypress/cypress.obj", 5, 3, 40, "cypress 2"),
                place("scopia/cypress/cypress.obj", -6, 6, 80, "cypress 3")]
    return {
        "name": "park (seed 002's small scene: a bench in a park)",
        "description": "Benches, a trash can, park lights and cypresses on a lawn (Sweet Home 3D furniture, Debian "
                       "sweethome3d-furniture); a low sun. The camera circles the bench.",
        "camera": {"position": [6.5, 2.6, 5.5], "target": [-1.5, 0.5, 0.5], "fov_deg": 50, "near": 0.1, "far": 80},
        "camera_path": {"position": orbit([-1.5, 0, 0.5], 7.5, 2.6, 24), "target": [[0, -1.5, 0.5, 0.5]]},
        "ambient": [0.12, 0.13, 0.15], "background": [0.45, 0.6, 0.8], "fog": {"start": 40, "end": 75},
        "technique": "pcf-poisson16",
        "lights": [{"type": "directional", "name": "sun", "direction": [-0.5, -0.75, -0.45], "color": [1, 0.95, 0.85],
                    "intensity": 1.0, "size": 1.0, "shadow": {"resolution": 2048}}],
        "objects": objects}


def scaffolding(x0, z, bays, levels, bay=2.0, lift=2.0):
    """A tube-and-plank scaffold along x in front of a wall: thin geometry that shadow maps alias."""
    steel, wood = [0.55, 0.57, 0.6], [0.6, 0.45, 0.28]
    parts, height = [], levels * lift + 1.0
    for i in range(bays + 1):
        for dz in (0.0, 1.0):
            parts.append(box(f"standard {i}{'ab'[int(dz)]}", [0.05, height, 0.05], [x0 + i * bay, height / 2, z + dz], steel))
    length = bays * bay
    for k in range(1, levels + 1):
        y = k * lift
        for dz in (0.0, 1.0):
            parts.append(box(f"ledger {k}{'ab'[int(dz)]}", [length, 0.04, 0.04], [x0 + length / 2, y, z + dz], steel))
            parts.append(box(f"guard rail {k}{'ab'[int(dz)]}", [length, 0.04, 0.04], [x0 + length / 2, y + 1.0, z + dz], steel))
        for p in range(4):
            parts.append(box(f"plank {k}.{p}", [length, 0.04, 0.22], [x0 + length / 2, y + 0.04, z + 0.14 + p * 0.24], wood))
    for i in range(bays):  # a diagonal brace per bay on the outer face
        angle = math.degrees(math.atan2(lift * levels, bay))
        parts.append(box(f"brace {i}", [math.hypot(bay, lift * levels), 0.04, 0.04],
                         [x0 + i * bay + bay / 2, lift * levels / 2, z + 1.05], steel, rotation=[0, 0, angle]))
    return parts


def construction():
    concrete, dirt = [0.7, 0.69, 0.66], [0.5, 0.42, 0.33]
    objects = [plane("site ground", [40, 40], [0, 0, 0], dirt),
               box("building shell left", [4, 7, 6], [-5, 3.5, -6], concrete),
               box("building shell right", [4, 7, 6], [5, 3.5, -6], concrete),
               box("building floor slab", [6, 0.3, 6], [0, 3.5, -6], concrete),
               box("building roof slab", [14, 0.3, 6], [0, 7.15, -6], concrete)]
    objects += scaffolding(-7, -2.9, 7, 3)
    objects += [place("scopia/step-ladder-metal/step-ladder-metal.obj", 3.5, 0.5, 20, "step ladder"),
                place("blendswap-cc-0/wheelbarrow/wheelbarrow.obj", -1.5, 2.5, 30, "wheelbarrow"),
                place("blendswap-cc-0/pallet/pallet.obj", 5.5, 3, 0, "pallet"),
                place("blendswap-cc-0/crate/crate.obj", 5.5, 3, 10, "crate", y=0.12),
                place("blendswap-cc-0/pallet/pallet.obj", 7, 3.2, 15, "pallet 2"),
                place("blendswap-cc-0/barrel/barrel.obj", 7.3, 1.2, 0, "barrel"),
                place("blendswap-cc-0/barrel/barrel.obj", 8.2, 1.6, 0, "barrel 2"),
                place("scopia/table-on-trestles/table-on-trestles.obj", 0.5, 4.5, 0, "table on trestles"),
                place("scopia/wood_logs/wood_logs.obj", 2.6, 4.6, 90, "wood"),
                place("scopia/wood_logs/wood_logs.obj", 3.1, 4.8, 80, "wood 2")]
    for i in range(5):  # site fence of pedestrian railings, thin bars
        objects.append(place("blendswap-cc-0/pedestrianRailing1/pedestrianRailing1.obj", -4.2 + i * 2.1, 7.5, 0, f"railing {i}"))
    for i in range(6):
        objects.append(place("scopia/cone/cone.obj", -8 + i * 1.2, 6.2, 0, f"cone {i}"))
    return {
        "name": "construction site (seed 002's medium scene)",
        "description": "A concrete shell behind a tube-and-plank scaffold, railings, a ladder and site clutter "
                       "(Sweet Home 3D furniture): thin geometry whose shadows alias on coarse maps.",
        "camera": {"position": [9, 3.5, 11], "target": [0, 2.0, -2], "fov_deg": 50, "near": 0.1, "far": 90},
        "camera_path": {"position": [[0, 9, 3.5, 11], [8, -3, 2.0, 9], [16, -10, 4.5, 6], [24, 9, 3.5, 11]],
                        "target": [[0, 0, 2.0, -2], [8, 1, 1.5, 0], [16, 0, 3.0, -3], [24, 0, 2.0, -2]]},
        "ambient": [0.12, 0.12, 0.13], "background": [0.55, 0.62, 0.72], "fog": {"start": 50, "end": 85},
        "technique": "cascaded",
        "lights": [{"type": "directional", "name": "sun", "direction": [-0.35, -0.8, 0.5], "color": [1, 0.96, 0.88],
                    "intensity": 1.0, "size": 0.6, "shadow": {"resolution": 2048}}],
        "objects": objects}


# Seed 002, Fig. 3.2: regions 1-5 plain shadow maps at five resolutions, 6 soft PCF, 7 LiSPSM.
STREET_REGIONS = [{"name": f"{i + 1}: shadow map {res}", "technique": "hard", "shadow_resolution": res}
                  for i, res in enumerate([256, 512, 1024, 2048, 4096])]
STREET_REGIONS += [{"name": "6: soft (PCF)", "technique": "pcf-poisson16", "shadow_resolution": 2048,
                    "parameters": {"radius_texels": 3}},
                   {"name": "7: LiSPSM", "technique": "lispsm", "shadow_resolution": 2048}]


def street():
    block = 12.0  # metres of street per region
    pavement, asphalt, facade = [0.66, 0.64, 0.6], [0.22, 0.22, 0.24], [0.78, 0.72, 0.62]
    objects = []
    for i, region in enumerate(STREET_REGIONS):
        g, x = region["name"], i * block + block / 2
        objects += [plane(f"pavement {i + 1}", [block, 4], [x, 0.0, -4], pavement, g),
                    plane(f"road {i + 1}", [block, 8], [x, 0.0, 2], asphalt, g),
                    box(f"facade {i + 1}", [block - 0.4, 6 + 2 * (i % 3), 1], [x, 3 + (i % 3), -6.5], facade, g),
                    box(f"kerb {i + 1}", [block, 0.15, 0.2], [x, 0.075, -2.0], pavement, g),
                    place("katorlegaz/classic-lamppost/classic-lamppost.obj", x - 4, -2.6, 0, f"lamppost {i + 1}", g),
                    place("katorlegaz/bench/bench.obj", x, -4.8, 0, f"bench {i + 1}", g),
                    place("katorlegaz/park-trashcan/park-trashcan.obj", x + 1.6, -4.9, 0, f"trash can {i + 1}", g),
                    place("scopia/cypress/cypress.obj", x + 4, -4.2, 30 * i, f"cypress {i + 1}", g),
                    place("scopia/smart-car/smart-car.obj" if i % 2 else "scopia/peugeot-308/peugeot-308.obj",
                          x - 1, -0.6, 90, f"car {i + 1}", g)]
    length = block * len(STREET_REGIONS)
    return {
        "name": "street (seed 002's large scene, with its combined technique)",
        "description": "Seven blocks of street, each a region with its own shadow technique (seed 002, Fig. 3.2): "
                       "regions 1-5 shadow maps of 256..4096 texels, 6 soft PCF, 7 LiSPSM. Walk along it and "
                       "compare; --technique NAME draws the whole street with one technique instead.",
        "camera": {"position": [-3, 1.7, 1.5], "target": [8, 1.0, -3.5], "fov_deg": 55, "near": 0.1, "far": 120},
        "camera_path": {"position": [[0, -3, 1.7, 1.5], [40, length - 6, 1.7, 1.5], [44, length - 6, 1.7, 1.5], [84, -3, 1.7, 1.5]],
                        "target": [[0, 8, 1.0, -3.5], [40, length + 4, 1.0, -3.5], [44, length - 16, 1.0, -3.5], [84, 8, 1.0, -3.5]]},
        "ambient": [0.12, 0.12, 0.14], "background": [0.5, 0.6, 0.75], "fog": {"start": 70, "end": 115},
        "technique": "hard",
        "regions": STREET_REGIONS,
        "lights": [{"type": "directional", "name": "sun", "direction": [0.45, -0.5, -0.75], "color": [1, 0.95, 0.85],
                    "intensity": 1.0, "size": 0.5, "shadow": {"resolution": 2048}}],
        "objects": objects}


def glass():
    def pane(name, size, position, rotation, colour, transmission):
        return {"name": name, "shape": "box", "size": size, "position": position, "rotation_deg": rotation,
                "material": {"diffuse": colour, "specular": [0.8, 0.8, 0.8], "shininess": 120, "alpha": 1.0,
                             "transmission": transmission}}
    objects = [plane("floor", [24, 24], [0, 0, 0], [0.85, 0.85, 0.83]),
               box("back wall", [24, 6, 0.2], [0, 3, -4], [0.9, 0.9, 0.9]),
               pane("red pane", [1.6, 2.0, 0.04], [-1.2, 1.4, 0.4], [0, 20, 0], [0.9, 0.1, 0.1], [0.9, 0.1, 0.1]),
               pane("green pane", [1.6, 2.0, 0.04], [0.0, 1.4, 0.9], [0, -10, 0], [0.1, 0.9, 0.1], [0.1, 0.9, 0.1]),
               pane("blue pane", [1.6, 2.0, 0.04], [1.2, 1.4, 0.4], [0, -30, 0], [0.15, 0.2, 0.95], [0.15, 0.25, 0.95]),
               pane("yellow block", [0.8, 0.8, 0.8], [-0.6, 0.4, 2.2], [0, 35, 0], [0.95, 0.85, 0.1], [0.95, 0.85, 0.1]),
               {"name": "cyan glass ball", "shape": "sphere", "radius": 0.45, "position": [0.9, 0.45, 2.3],
                "material": {"diffuse": [0.1, 0.85, 0.85], "specular": [0.9, 0.9, 0.9], "shininess": 150, "alpha": 1.0,
                             "transmission": [0.1, 0.85, 0.85]},
                "animation": [[0, 0.9, 0.45, 2.3], [3, 0.0, 0.45, 3.0], [6, -1.2, 0.45, 2.6], [9, 0.9, 0.45, 2.3]]},
               box("grey post", [0.3, 2.4, 0.3], [2.6, 1.2, 1.6], [0.5, 0.5, 0.5])]
    return {
        "name": "coloured glass (seed 000's kind of scene)",
        "description": "Red, green and blue panes, a yellow glass block and a moving cyan glass ball whose coloured "
                       "shadows overlap and multiply on the floor and the wall, under a sun and a spot light.",
        "camera": {"position": [0.5, 4.2, 8.0], "target": [0, 0.8, 0.5], "fov_deg": 45, "near": 0.1, "far": 50},
        "camera_path": {"position": [[0, 0.5, 4.2, 8.0], [6, 5.5, 3.0, 5.0], [12, 0.5, 5.0, 6.5], [18, -5.0, 3.0, 5.5],
                                     [24, 0.5, 4.2, 8.0]],
                        "target": [[0, 0, 0.8, 0.5]]},
        "ambient": [0.1, 0.1, 0.12], "background": [0.2, 0.22, 0.26],
        "technique": "cssm2",
        "lights": [{"type": "directional", "name": "sun", "direction": [0.5, -0.55, -0.65], "color": [1, 1, 1],
                    "intensity": 0.9, "size": 0.4, "shadow": {"resolution": 2048}},
                   {"type": "spot", "name": "spot", "position": [-3.5, 4.5, 4.0], "direction": [0.5, -0.7, -0.6],
                    "angle_deg": 50, "color": [1, 0.95, 0.9], "intensity": 1.2, "range": 20, "size": 0.1,
                    "shadow": {"resolution": 1024}}],
        "objects": objects}


def main():
    for name, scene in [("park", park()), ("construction", construction()), ("street", street()), ("glass", glass())]:
        path = os.path.join(ROOT, "scenes", name + ".json")
        with open(path, "w") as f:
            json.dump(scene, f, indent=1)
            f.write("\n")
        print(f"wrote {os.path.relpath(path, ROOT)}: {len(scene['objects'])} objects")


if __name__ == "__main__":
    main()
