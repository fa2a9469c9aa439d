# Builds an Unreal Engine material from a Relief export: run it in the Unreal Editor
# (Tools > Execute Python Script, or `py "<this file>"` in the Output Log) with the Python
# Editor Script Plugin enabled. It reads the manifest written beside it (MANIFEST, set by Relief
# above this comment), imports the textures with the settings the manifest names, and wires a
# material: base colour, normal, ORM (R occlusion, G roughness, B metallic), and Epic's
# ParallaxOcclusionMapping material function driving every texture's UVs when the manifest has
# a "parallax" entry. Wiring that fails is reported in the Output Log; the manifest says what
# goes where, so it can be finished by hand.
import json
import os

import unreal

HERE = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(HERE, MANIFEST), encoding="utf-8") as manifest_file:  # noqa: F821
    manifest = json.load(manifest_file)

destination = "/Game/Relief/" + manifest["name"]
tools = unreal.AssetToolsHelpers.get_asset_tools()
library = unreal.MaterialEditingLibrary


def import_texture(entry):
    task = unreal.AssetImportTask()
    task.filename = os.path.join(HERE, entry["file"])
    task.destination_path = destination
    task.automated = True
    task.replace_existing = True
    task.save = False
    tools.import_asset_tasks([task])
    texture = unreal.load_asset(task.imported_object_paths[0])
    texture.set_editor_property("srgb", entry["srgb"])
    texture.set_editor_property(
        "compression_settings", getattr(unreal.TextureCompressionSettings, entry["compression"]))
    unreal.EditorAssetLibrary.save_loaded_asset(texture)
    return texture


def connect(source, output, target, target_input):
    if not library.connect_material_expressions(source, output, target, target_input):
        unreal.log_warning("Relief: could not connect %s to %s; see the manifest" %
                           (output or "the output", target_input))


textures = {key: import_texture(entry) for key, entry in manifest["textures"].items()}
material = tools.create_asset(manifest["material"], destination, unreal.Material,
                              unreal.MaterialFactoryNew())

coordinates = library.create_material_expression(
    material, unreal.MaterialExpressionTextureCoordinate, -1400, 0)
coordinates.set_editor_property("utiling", manifest["parameters"]["Tiling"])
coordinates.set_editor_property("vtiling", manifest["parameters"]["Tiling"])
uv_source, uv_output = coordinates, ""

parallax = manifest.get("parallax")
if parallax and "Height" in textures:
    pom = library.create_material_expression(
        material, unreal.MaterialExpressionMaterialFunctionCall, -900, 0)
    pom.set_editor_property("material_function", unreal.load_asset(parallax["function"]))
    height = library.create_material_expression(
        material, unreal.MaterialExpressionTextureObjectParameter, -1400, 200)
    height.set_editor_property("parameter_name", "Height")
    height.set_editor_property("texture", textures["Height"])
    connect(height, "", pom, "Heightmap Texture")
    connect(coordinates, "", pom, "UVs")
    channel = library.create_material_expression(
        material, unreal.MaterialExpressionConstant4Vector, -1400, 400)
    channel.set_editor_property("constant", unreal.LinearColor(*parallax["HeightmapChannel"]))
    connect(channel, "", pom, "Heightmap Channel")
    for row, name in enumerate(("HeightRatio", "MinSteps", "MaxSteps", "ReferencePlane")):
        scalar = library.create_material_expression(
            material, unreal.MaterialExpressionScalarParameter, -1400, 600 + 120 * row)
        scalar.set_editor_property("parameter_name", name)
        scalar.set_editor_property("default_value", parallax[name])
        connect(scalar, "", pom, parallax["inputs"][name])
    uv_source, uv_output = pom, "Parallax UVs"
    if parallax.get("PixelDepthOffset"):
        library.connect_material_property(pom, "Pixel Depth Offset",
                                          unreal.MaterialProperty.MP_PIXEL_DEPTH_OFFSET)

SAMPLERS = {"BaseColor": "SAMPLERTYPE_COLOR", "Normal": "SAMPLERTYPE_NORMAL",
            "ORM": "SAMPLERTYPE_MASKS"}
OUTPUTS = {"BaseColor": [("RGB", "MP_BASE_COLOR")], "Normal": [("RGB", "MP_NORMAL")],
           "ORM": [("R", "MP_AMBIENT_OCCLUSION"), ("G", "MP_ROUGHNESS"), ("B", "MP_METALLIC")]}
for row, key in enumerate(("BaseColor", "Normal", "ORM")):
    if key not in textures:
        continue
    sample = library.create_material_expression(
        material, unreal.MaterialExpressionTextureSampleParameter2D, -400, 300 * row)
    sample.set_editor_property("parameter_name", key)
    sample.set_editor_property("texture", textures[key])
    sample.set_editor_property("sampler_type", getattr(unreal.MaterialSamplerType, SAMPLERS[key]))
    connect(uv_source, uv_output, sample, "UVs")
    for output, target in OUTPUTS[key]:
        library.connect_material_property(sample, output, getattr(unreal.MaterialProperty, target))

for row, (name, value) in enumerate(manifest.get("constants", {}).items()):
    scalar = library.create_material_expression(
        material, unreal.MaterialExpressionScalarParameter, -400, 1000 + 120 * row)
    scalar.set_editor_property("parameter_name", name)
    scalar.set_editor_property("default_value", value)
    library.connect_material_property(scalar, "", getattr(unreal.MaterialProperty, "MP_" + name.upper()))

library.recompile_material(material)
unreal.EditorAssetLibrary.save_loaded_asset(material)
unreal.log("Relief: made %s/%s" % (destination, manifest["material"]))
