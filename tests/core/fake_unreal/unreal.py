"""A stand-in for the Unreal Editor's `unreal` module, for running Relief's Unreal import script
outside Unreal (tests/core/EngineExportTest.cpp). It only records what the script asks for:
imported files and their settings, material expressions with their properties, and every
connection, and writes them as JSON to $RELIEF_FAKE_UNREAL_LOG when the script saves the
material. Names the script uses that the real module lacks would still pass here; the test
checks the names against the ones the script is meant to use."""
import json
import os

record = {"imports": [], "textures": {}, "expressions": [], "links": [], "properties": []}


class _Enum:
    """TextureCompressionSettings, MaterialProperty, MaterialSamplerType: names read back."""

    def __getattr__(self, name):
        return name


TextureCompressionSettings = _Enum()
MaterialProperty = _Enum()
MaterialSamplerType = _Enum()


class _Object:
    def __init__(self, kind="", name=""):
        self.kind, self.name, self.properties = kind, name, {}

    def set_editor_property(self, key, value):
        self.properties[key] = value if isinstance(value, (int, float, str, bool, list)) else \
            getattr(value, "name", repr(value))


class LinearColor(list):
    def __init__(self, *values):
        super().__init__(values)


class AssetImportTask:
    def __init__(self):
        self.imported_object_paths = []


class _AssetTools:
    def import_asset_tasks(self, tasks):
        for task in tasks:
            record["imports"].append({"file": task.filename, "destination": task.destination_path})
            task.imported_object_paths = [task.filename]

    def create_asset(self, name, path, cls, factory):
        return _Object("Material", path + "/" + name)


class AssetToolsHelpers:
    @staticmethod
    def get_asset_tools():
        return _AssetTools()


_loaded = {}


def load_asset(path):
    if path not in _loaded:
        _loaded[path] = _Object("Asset", os.path.basename(path))
        record["textures"][os.path.basename(path)] = _loaded[path].properties
    return _loaded[path]


class EditorAssetLibrary:
    @staticmethod
    def save_loaded_asset(asset):
        if asset.kind == "Material":
            with open(os.environ["RELIEF_FAKE_UNREAL_LOG"], "w", encoding="utf-8") as out:
                json.dump(record, out, indent=1)
        return True


class MaterialEditingLibrary:
    @staticmethod
    def create_material_expression(material, cls, x, y):
        expression = _Object(cls, "e%d" % len(record["expressions"]))
        record["expressions"].append({"id": expression.name, "class": cls,
                                      "properties": expression.properties})
        return expression

    @staticmethod
    def connect_material_expressions(source, output, target, target_input):
        record["links"].append([source.name, output, target.name, target_input])
        return True

    @staticmethod
    def connect_material_property(source, output, prop):
        record["properties"].append([source.name, output, prop])
        return True

    @staticmethod
    def recompile_material(material):
        pass


for _name in ("MaterialExpressionTextureCoordinate", "MaterialExpressionMaterialFunctionCall",
              "MaterialExpressionTextureObjectParameter", "MaterialExpressionConstant4Vector",
              "MaterialExpressionScalarParameter", "MaterialExpressionTextureSampleParameter2D"):
    globals()[_name] = _name
Material = "Material"


def MaterialFactoryNew():
    return None


def log(message):
    print(message)


def log_warning(message):
    print("warning:", message)
