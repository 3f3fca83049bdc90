#!/usr/bin/env python3
"""Writes Candela's own small test scenes for the glTF extensions the Khronos sample models show
but ../shared/assets does not hold: rows of spheres and planes sweeping each parameter, as the
Khronos test models do. Each scene is one self-contained .glb in assets/test-scenes/.

    tools/make-test-scenes.py [OUT_DIR]      (default: assets/test-scenes)

Scenes (see assets/test-scenes/README.md for what each row shows):
  DispersionSweep.glb            KHR_materials_dispersion over KHR_materials_volume
  DiffuseTransmissionSweep.glb   KHR_materials_diffuse_transmission, lit from behind
  AnimationPointerSweep.glb      KHR_animation_pointer: material factors, a texture transform,
                                 a light, a camera
  NodeVisibility.glb             KHR_node_visibility, static and animated through pointers
Deterministic: the same script writes the same bytes. Pure Python (no third-party packages).
"""
import json
import math
import struct
import sys
import zlib
from pathlib import Path

FLOAT, UBYTE, USHORT = 5126, 5121, 5123


class Glb:
    """A glTF document with one binary buffer, written as GLB."""

    def __init__(self, generator):
        self.doc = {"asset": {"version": "2.0", "generator": generator}, "scene": 0, "scenes": [{"nodes": []}],
                    "nodes": [], "meshes": [], "materials": [], "accessors": [], "bufferViews": []}
        self.bin = bytearray()

    def view(self, data):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)})
        self.bin += data
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, values, kind, component=FLOAT, minmax=False):
        width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        fmt = {FLOAT: "f", UBYTE: "B", USHORT: "H"}[component]
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        a = {"bufferView": self.view(data), "componentType": component, "count": len(values) // width, "type": kind}
        if minmax:
            a["min"] = [min(values[i::width]) for i in range(width)]
            a["max"] = [max(values[i::width]) for i in range(width)]
        self.doc["accessors"].append(a)
        return len(self.doc["accessors"]) - 1

    def add(self, key, item):
        self.doc.setdefault(key, []).append(item)
        return len(self.doc[key]) - 1

    def node(self, node, root=True):
        index = self.add("nodes", node)
        if root:
            self.doc["scenes"][0]["nodes"].append(index)
        return index

    def extension(self, name, required=False):
        self.doc.setdefault("extensionsUsed", [])
        if name not in self.doc["extensionsUsed"]:
            self.doc["extensionsUsed"].append(name)
        if required and name not in self.doc.setdefault("extensionsRequired", []):
            self.doc["extensionsRequired"].append(name)

    def write(self, path):
        self.doc["buffers"] = [{"byteLength": len(self.bin)}]
        doc = {k: v for k, v in self.doc.items() if v != []}
        text = json.dumps(doc, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        binary = bytes(self.bin) + b"\0" * (-len(self.bin) % 4)
        total = 12 + 8 + len(text) + 8 + len(binary)
        out = struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") + text
        out += struct.pack("<I4s", len(binary), b"BIN\0") + binary
        Path(path).write_bytes(out)


def sphere_geometry(glb, rings=24, segments=48):
    """A unit UV sphere's accessors (POSITION, NORMAL, TEXCOORD_0 and indices), shared by every mesh."""
    pos, nrm, uv, idx = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            p = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            pos += p
            nrm += p
            uv += (s / segments, r / rings)
    for r in range(rings):
        for s in range(segments):
            a, b = r * (segments + 1) + s, (r + 1) * (segments + 1) + s
            idx += (a, b, a + 1, a + 1, b, b + 1)
    return {"POSITION": glb.accessor(pos, "VEC3", minmax=True), "NORMAL": glb.accessor(nrm, "VEC3"),
            "TEXCOORD_0": glb.accessor(uv, "VEC2")}, glb.accessor(idx, "SCALAR", USHORT)


def quad_geometry(glb, width, height):
    """A quad in the XY plane facing +Z, centred at the origin, UVs 0..1 (top-left first)."""
    w, h = width / 2, height / 2
    pos = [-w, -h, 0, w, -h, 0, w, h, 0, -w, h, 0]
    return {"POSITION": glb.accessor(pos, "VEC3", minmax=True), "NORMAL": glb.accessor([0, 0, 1] * 4, "VEC3"),
            "TEXCOORD_0": glb.accessor([0, 1, 1, 1, 1, 0, 0, 0], "VEC2")}, glb.accessor([0, 1, 2, 0, 2, 3], "SCALAR", USHORT)


def mesh(glb, geometry, material):
    attributes, indices = geometry
    return glb.add("meshes", {"primitives": [{"attributes": attributes, "indices": indices, "material": material}]})


def checker_png(size=64, cells=8):
    """A grey/white checkerboard with a coloured stripe, as an RGB PNG (stored by zlib)."""
    rows = bytearray()
    for y in range(size):
        rows.append(0)
        for x in range(size):
            on = ((x * cells // size) + (y * cells // size)) % 2
            stripe = size // 2 - 3 <= y < size // 2 + 3
            rows += bytes((230, 60, 40)) if stripe else bytes((235, 235, 235) if on else (60, 60, 60))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b""))


def backdrop(glb, z=-2.0, width=9.0, height=5.0):
    """A checkered plane behind the spheres (what transmission and dispersion are seen against)."""
    image = glb.add("images", {"bufferView": glb.view(checker_png()), "mimeType": "image/png"})
    glb.add("samplers", {"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497})
    texture = glb.add("textures", {"source": image, "sampler": 0})
    material = glb.add("materials", {"name": "backdrop", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": texture, "extensions": {"KHR_texture_transform": {"scale": [3, 1.6]}}},
        "metallicFactor": 0, "roughnessFactor": 0.8}})
    glb.extension("KHR_texture_transform")
    glb.node({"name": "backdrop", "mesh": mesh(glb, quad_geometry(glb, width, height), material), "translation": [0, 0, z]})


def sphere_row(glb, geometry, materials, y, spacing=1.5, radius=0.6):
    for i, material in enumerate(materials):
        x = (i - (len(materials) - 1) / 2) * spacing
        glb.node({"name": glb.doc["materials"][material]["name"], "mesh": mesh(glb, geometry, material),
                  "translation": [x, y, 0], "scale": [radius] * 3})


def dispersion_sweep(path):
    glb = Glb("tools/make-test-scenes.py")
    for name in ("KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior", "KHR_materials_dispersion"):
        glb.extension(name)
    backdrop(glb)
    sphere = sphere_geometry(glb)
    # Rows: IOR 1.5 and 2.4 (diamond); columns: dispersion 0 (none), 0.33 (crown glass), 1 (Abbe 20),
    # 2.04 (rutile), 10 (exaggerated).
    for y, ior in ((0.9, 1.5), (-0.9, 2.4)):
        materials = []
        for dispersion in (0.0, 0.33, 1.0, 2.04, 10.0):
            materials.append(glb.add("materials", {
                "name": "ior %.1f dispersion %g" % (ior, dispersion),
                "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0},
                "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
                               "KHR_materials_volume": {"thicknessFactor": 1.2},
                               "KHR_materials_ior": {"ior": ior},
                               "KHR_materials_dispersion": {"dispersion": dispersion}}}))
        sphere_row(glb, sphere, materials, y)
    glb.write(path)


def diffuse_transmission_sweep(path):
    glb = Glb("tools/make-test-scenes.py")
    for name in ("KHR_materials_diffuse_transmission", "KHR_materials_volume", "KHR_lights_punctual"):
        glb.extension(name)
    quad = quad_geometry(glb, 1.2, 1.2)
    # Thin leaves (quads, double-sided) lit from behind by a warm spot light, and spheres with a volume.
    # A warm spot light behind (shining toward the viewer) and a dim white light from the front.
    glb.doc.setdefault("extensions", {})["KHR_lights_punctual"] = {"lights": [
        {"type": "spot", "color": [1, 0.9, 0.75], "intensity": 60, "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.9}},
        {"type": "directional", "color": [1, 1, 1], "intensity": 0.6}]}
    glb.node({"name": "light behind", "translation": [0, 0, -4], "rotation": [0, 1, 0, 0],
              "extensions": {"KHR_lights_punctual": {"light": 0}}})
    glb.node({"name": "front light", "rotation": [-0.2588, 0, 0, 0.9659], "extensions": {"KHR_lights_punctual": {"light": 1}}})
    for row, (y, colour) in enumerate(((0.9, [1, 1, 1]), (-0.6, [1, 0.25, 0.1]))):
        for i, factor in enumerate((0.0, 0.25, 0.5, 0.75, 1.0)):
            material = glb.add("materials", {
                "name": "leaf factor %g colour %d" % (factor, row), "doubleSided": True,
                "pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.6, 0.2, 1], "metallicFactor": 0, "roughnessFactor": 0.6},
                "extensions": {"KHR_materials_diffuse_transmission": {"diffuseTransmissionFactor": factor,
                                                                      "diffuseTransmissionColorFactor": colour}}})
            glb.node({"name": "leaf %g %d" % (factor, row), "mesh": mesh(glb, quad, material),
                      "translation": [(i - 2) * 1.5, y, 0]})
    sphere = sphere_geometry(glb)
    materials = []
    for thickness in (0.0, 0.2, 1.0):
        materials.append(glb.add("materials", {
            "name": "wax thickness %g" % thickness,
            "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.85, 0.7, 1], "metallicFactor": 0, "roughnessFactor": 0.35},
            "extensions": {"KHR_materials_diffuse_transmission": {"diffuseTransmissionFactor": 1,
                                                                  "diffuseTransmissionColorFactor": [1, 0.8, 0.5]},
                           "KHR_materials_volume": {"thicknessFactor": thickness, "attenuationDistance": 0.5,
                                                    "attenuationColor": [1, 0.5, 0.2]}}}))
    sphere_row(glb, sphere, materials, -2.0)
    glb.write(path)


def animation_pointer_sweep(path):
    glb = Glb("tools/make-test-scenes.py")
    for name in ("KHR_animation_pointer", "KHR_materials_emissive_strength", "KHR_texture_transform", "KHR_lights_punctual"):
        glb.extension(name)
    backdrop(glb)
    sphere = sphere_geometry(glb)
    checker = 0  # the backdrop's texture
    names = ["base colour", "roughness", "metallic", "emissive strength", "texture offset"]
    materials = []
    for name in names:
        m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1], "metallicFactor": 0,
                                                       "roughnessFactor": 0.4}}
        if name == "emissive strength":
            m["emissiveFactor"] = [1, 0.4, 0.1]
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 1}}
        if name == "texture offset":
            m["pbrMetallicRoughness"]["baseColorTexture"] = {
                "index": checker, "extensions": {"KHR_texture_transform": {"offset": [0, 0], "scale": [2, 1]}}}
        materials.append(glb.add("materials", m))
    sphere_row(glb, sphere, materials, 0.0)
    glb.doc.setdefault("extensions", {})["KHR_lights_punctual"] = {"lights": [
        {"type": "point", "color": [1, 1, 1], "intensity": 20}]}
    glb.node({"name": "light", "translation": [0, 2.5, 2], "extensions": {"KHR_lights_punctual": {"light": 0}}})
    glb.add("cameras", {"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.1, "aspectRatio": 1.5}})
    glb.node({"name": "camera", "camera": 0, "translation": [0, 0, 9]})
    # Four seconds, keys every second.
    times = glb.accessor([0, 1, 2, 3, 4], "SCALAR", minmax=True)
    channels, samplers = [], []

    def animate(pointer, values, kind, interpolation="LINEAR"):
        samplers.append({"input": times, "output": glb.accessor(values, kind), "interpolation": interpolation})
        channels.append({"sampler": len(samplers) - 1, "target": {"path": "pointer", "extensions": {
            "KHR_animation_pointer": {"pointer": pointer}}}})

    animate("/materials/1/pbrMetallicRoughness/baseColorFactor",
            [0.8, 0.1, 0.1, 1, 0.1, 0.8, 0.1, 1, 0.1, 0.1, 0.8, 1, 0.8, 0.8, 0.1, 1, 0.8, 0.1, 0.1, 1], "VEC4")
    animate("/materials/2/pbrMetallicRoughness/roughnessFactor", [0, 0.25, 0.5, 1, 0], "SCALAR")
    animate("/materials/3/pbrMetallicRoughness/metallicFactor", [0, 1, 0, 1, 0], "SCALAR", "STEP")
    animate("/materials/4/extensions/KHR_materials_emissive_strength/emissiveStrength", [1, 4, 8, 4, 1], "SCALAR")
    animate("/materials/5/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/offset",
            [0, 0, 0.25, 0, 0.5, 0, 0.75, 0, 1, 0], "VEC2")
    animate("/extensions/KHR_lights_punctual/lights/0/intensity", [20, 80, 5, 40, 20], "SCALAR")
    animate("/cameras/0/perspective/yfov", [0.6, 0.7, 0.8, 0.7, 0.6], "SCALAR")
    glb.add("animations", {"name": "pointers", "channels": channels, "samplers": samplers})
    glb.write(path)


def node_visibility(path):
    glb = Glb("tools/make-test-scenes.py")
    for name in ("KHR_node_visibility", "KHR_animation_pointer", "KHR_lights_punctual"):
        glb.extension(name)
    backdrop(glb)
    sphere = sphere_geometry(glb)
    colours = {"red": [0.8, 0.1, 0.1, 1], "green": [0.1, 0.7, 0.1, 1], "blue": [0.1, 0.2, 0.8, 1], "white": [0.9, 0.9, 0.9, 1]}
    material = {n: glb.add("materials", {"name": n, "pbrMetallicRoughness": {"baseColorFactor": c, "metallicFactor": 0,
                                                                             "roughnessFactor": 0.5}})
                for n, c in colours.items()}
    # Left: a visible sphere. Middle: a hidden parent whose child says visible (hidden: the parent wins).
    # Right: a sphere blinking every second, with a red point light under the same node.
    glb.node({"name": "visible", "mesh": mesh(glb, sphere, material["green"]), "translation": [-3, 0, 0]})
    child = glb.node({"name": "child of hidden (visible: true)", "mesh": mesh(glb, sphere, material["blue"]),
                      "translation": [0, -1.5, 0], "extensions": {"KHR_node_visibility": {"visible": True}}}, root=False)
    glb.node({"name": "hidden parent", "mesh": mesh(glb, sphere, material["white"]), "children": [child],
              "translation": [0, 0.75, 0], "extensions": {"KHR_node_visibility": {"visible": False}}})
    glb.doc.setdefault("extensions", {})["KHR_lights_punctual"] = {"lights": [
        {"type": "point", "color": [1, 0.1, 0.1], "intensity": 30}]}
    light = glb.node({"name": "its light", "translation": [0, 1.2, 1], "extensions": {"KHR_lights_punctual": {"light": 0}}},
                     root=False)
    blinking = glb.node({"name": "blinking", "mesh": mesh(glb, sphere, material["red"]), "children": [light],
                         "translation": [3, 0, 0], "extensions": {"KHR_node_visibility": {"visible": True}}})
    times = glb.accessor([0, 1, 2, 3], "SCALAR", minmax=True)
    values = glb.accessor([1, 0, 1, 0], "SCALAR", UBYTE)
    glb.add("animations", {"name": "blink", "samplers": [{"input": times, "output": values, "interpolation": "STEP"}],
                           "channels": [{"sampler": 0, "target": {"path": "pointer", "extensions": {"KHR_animation_pointer": {
                               "pointer": "/nodes/%d/extensions/KHR_node_visibility/visible" % blinking}}}}]})
    glb.write(path)


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "assets" / "test-scenes"
    out.mkdir(parents=True, exist_ok=True)
    for name, make in (("DispersionSweep", dispersion_sweep), ("DiffuseTransmissionSweep", diffuse_transmission_sweep),
                       ("AnimationPointerSweep", animation_pointer_sweep), ("NodeVisibility", node_visibility)):
        make(out / (name + ".glb"))
        print(out / (name + ".glb"))


if __name__ == "__main__":
    main()
