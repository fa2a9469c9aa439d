#!/usr/bin/env bash
# Writes the fuzz targets' seed inputs (small valid files of every kind each reader accepts)
# into tests/fuzz/corpus/<target>/seed-*. Run once when a reader learns a new kind of file; the
# seeds are committed, so CI does not run this. Needs a built relief-cli (first argument) and
# oiiotool/maketx (openimageio-tools).
set -euo pipefail
cli=${1:?usage: make-seeds.sh path/to/relief-cli}
cd "$(dirname "$0")/../.."
corpus=tests/fuzz/corpus
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$corpus"/{dds,ktx2,png,tiff,exr,preset,gltf,glb,obj}

# Images: the bit depths, channel counts, layouts and compressions artists' files use.
oiiotool --pattern checker:width=2:height=2 8x8 3 -d uint8 -o "$corpus/png/seed-rgb8.png"
oiiotool --pattern fill:top=0:bottom=1 6x5 1 -d uint16 -o "$corpus/png/seed-grey16.png"
oiiotool --pattern checker 4x4 4 -d uint8 -o "$corpus/png/seed-rgba8.png"
oiiotool --pattern fill:left=0,0:right=1,1 7x3 2 -d uint8 -o "$corpus/png/seed-greyalpha.png"
oiiotool --pattern checker 9x7 3 -d uint8 -o "$corpus/tiff/seed-strips8.tif"
oiiotool --pattern fill:top=0:bottom=1 20x18 1 -d uint16 --compression lzw -o "$corpus/tiff/seed-lzw16.tif"
oiiotool --pattern checker 20x18 3 -d float --tile 16 16 -o "$corpus/tiff/seed-tiledfloat.tif"
oiiotool --pattern checker 5x6 4 -d uint8 --compression zip -o "$corpus/tiff/seed-rgbazip.tif"
oiiotool --pattern checker 8x8 3 -d half -o "$corpus/exr/seed-half.exr"
oiiotool --pattern fill:top=0:bottom=1 6x5 1 -d float --compression none -o "$corpus/exr/seed-float.exr"
oiiotool --pattern checker 20x18 3 -d half -o "$work/mip.exr"
maketx "$work/mip.exr" --tile 16 16 -o "$corpus/exr/seed-tiledmip.exr" >/dev/null
oiiotool --pattern checker 9x9 4 -d half --compression piz -o "$corpus/exr/seed-piz.exr"

# Textures: every format in each container that holds it, with and without mips.
oiiotool --pattern checker:width=2:height=2 8x8 4 -d uint8 -o "$work/map.png"
for format in bc1 bc2 bc3 bc4 bc5 dxt5nm bc7 etc1 etc2 etc2a eac-r11 eac-rg11 astc4x4 astc6x6; do
  for container in dds ktx2; do
    options=()
    case $format in bc3|bc7|etc2) options+=(--mips) ;; esac
    case $format in bc5|dxt5nm|eac-rg11) options+=(--normal) ;; esac
    # Formats a container cannot hold (ETC and ASTC in DDS) are refused; no seed then.
    if "$cli" compress --in "$work/map.png" --format "$format" "${options[@]}" \
        --out "$work/t.$container" >/dev/null 2>&1; then
      cp "$work/t.$container" "$corpus/$container/seed-$format.$container"
    fi
  done
done

# Zstandard-supercompressed KTX2 (scheme 2), with mips.
"$cli" compress --in "$work/map.png" --format bc1 --mips --zstd 9 --out "$corpus/ktx2/seed-bc1-zstd.ktx2" >/dev/null
"$cli" compress --in "$work/map.png" --format astc4x4 --zstd 3 --out "$corpus/ktx2/seed-astc4x4-zstd.ktx2" >/dev/null

# Presets: the samples, a version 1 file and one with compression choices and a view.
for preset in samples/*/*.relief; do cp "$preset" "$corpus/preset/seed-$(basename "$preset")"; done
cat >"$corpus/preset/seed-version1.relief" <<'JSON'
{"format": "relief-material", "version": 1, "technique": "pom",
 "parameters": {"heightScale": 0.05, "minSamples": 8, "maxSamples": 32},
 "maps": {"height": {"path": "h.png"}}}
JSON
cat >"$corpus/preset/seed-view.relief" <<'JSON'
{"format": "relief-material", "version": 2, "name": "v", "technique": "relief",
 "maps": {"normal": {"path": "n.png", "colorSpace": "linear",
                     "compression": {"format": "bc5", "quality": "fast", "mipmaps": true,
                                     "zstd": 9}}},
 "view": {"mesh": "sphere", "camera": {"yaw": 30, "pitch": 20, "distance": 3},
          "light": {"azimuth": 45, "elevation": 30, "color": [1, 0.9, 0.8], "intensity": 1}}}
JSON

# Meshes: a textured quad as OBJ, glTF (external and embedded buffer) and glb.
cat >"$corpus/obj/seed-quad.obj" <<'OBJ'
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
f 1/1/1 2/2/1 3/3/1
f 1/1/1 3/3/1 4/4/1
OBJ
python3 - "$corpus" <<'PY'
import base64, json, struct, sys
corpus = sys.argv[1]
positions = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]
uvs = [0, 0, 1, 0, 1, 1, 0, 1]
indices = [0, 1, 2, 0, 2, 3]
blob = struct.pack("12f", *positions) + struct.pack("8f", *uvs) + struct.pack("6H", *indices)
blob += b"\0" * (-len(blob) % 4)
def document(uri):
    buffer = {"byteLength": len(blob)}
    if uri:
        buffer["uri"] = uri
    return {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "children": [1]}, {"mesh": 0, "translation": [0, 0, 1]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2}]}],
        "buffers": [buffer],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
embedded = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
with open(f"{corpus}/gltf/seed-embedded.gltf", "w") as f:
    json.dump(document(embedded), f)
with open(f"{corpus}/gltf/seed-external.gltf", "w") as f:
    json.dump(document("quad.bin"), f)
text = json.dumps(document(None)).encode()
text += b" " * (-len(text) % 4)
glb = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(blob))
glb += struct.pack("<II", len(text), 0x4E4F534A) + text
glb += struct.pack("<II", len(blob), 0x004E4942) + blob
with open(f"{corpus}/glb/seed-quad.glb", "wb") as f:
    f.write(glb)
PY
echo "seeds: $(find "$corpus" -name 'seed-*' | wc -l) files in $corpus"
