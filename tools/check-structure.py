#!/usr/bin/env python3
"""Checks two rules of docs/architecture.md and docs/extending.md that the compiler cannot:

1. Inside core/, a folder includes only folders at or below it in the layer order below (the
   CMake link lists keep core, renderer, ui and app apart; inside relief_core one library holds
   every folder, so nothing else would notice an include running back up).
2. A switch over one of the enums an extension adds values to (formats, techniques, map slots,
   debug views, export kinds...) has no `default:`, so that -Wswitch (on in every build, an
   error with RELIEF_STRICT) names each place a new value must be handled.

Usage: tools/check-structure.py [SOURCE_ROOT]. Prints each violation as file:line: message and
exits 1 if there is one. Run by CTest as lint.structure.
"""
import pathlib
import re
import sys

# Lowest first: a folder may include itself and any folder before it.
CORE_LAYERS = [
    "base", "image", "material", "mesh", "view", "tracing", "compression", "generators",
    "shading", "preset", "exporters",
]

# The enums that grow when Relief is extended (docs/extending.md), plus their close relatives
# whose switches must grow with them.
EXTENSION_ENUMS = [
    "TextureFormat", "FormatFamily", "FormatLayout", "GpuFeature", "TextureContainer",
    "Technique", "MapSlot", "DebugView", "ExportKind", "GeneratorKind", "PackageMapFormat",
    "PackageTextures", "UnityPipeline", "ToneMapper", "Background", "ShadowMode",
    "ShadingModel", "PrimitiveShape", "BuiltInEnvironment", "CompressionQuality", "MapTexels",
    "ParamKind", "ViewScale", "Ktx2Samples",
]
CASE_OF_ENUM = re.compile(r"\bcase\s+(?:[\w:]*::)?(" + "|".join(EXTENSION_ENUMS) + r")::\w+")
INCLUDE = re.compile(r'^\s*#\s*include\s+"core/(\w+)/', re.MULTILINE)
SWITCH = re.compile(r"\bswitch\s*\(")
DEFAULT = re.compile(r"\bdefault\s*:")


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def strip_comments_and_strings(text):
    """Blanks comments and string literals, keeping offsets and newlines."""
    def blank(match):
        return re.sub(r"[^\n]", " ", match.group(0))
    pattern = r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\''
    return re.sub(pattern, blank, text, flags=re.DOTALL)


def check_core_layers(root, problems):
    for path in sorted((root / "core").rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        folder = path.relative_to(root / "core").parts[0]
        if folder not in CORE_LAYERS:
            problems.append(f"{path}:1: core/{folder} is not in the layer order of "
                            "tools/check-structure.py")
            continue
        text = path.read_text(encoding="utf-8")
        for match in INCLUDE.finditer(text):
            target = match.group(1)
            if target not in CORE_LAYERS:
                continue
            if CORE_LAYERS.index(target) > CORE_LAYERS.index(folder):
                problems.append(f"{path}:{line_of(text, match.start())}: core/{folder} includes "
                                f"core/{target}, which sits above it")


def switch_body(code, start):
    """The text between the braces of the switch whose keyword is at `start`."""
    open_brace = code.find("{", start)
    if open_brace < 0:
        return None, None
    depth = 0
    for i in range(open_brace, len(code)):
        if code[i] == "{":
            depth += 1
        elif code[i] == "}":
            depth -= 1
            if depth == 0:
                return open_brace + 1, i
    return None, None


def top_level(code, begin, end):
    """The switch body with nested switches blanked out (their defaults are their own)."""
    body = list(code[begin:end])
    for match in SWITCH.finditer(code, begin, end):
        inner_begin, inner_end = switch_body(code, match.start())
        if inner_begin is None or inner_end > end:
            continue
        for i in range(match.start(), inner_end):
            if body[i - begin] != "\n":
                body[i - begin] = " "
    return "".join(body)


def check_switch_defaults(root, problems):
    for folder in ("core", "renderer", "ui", "app"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".h", ".cpp"):
                continue
            code = strip_comments_and_strings(path.read_text(encoding="utf-8"))
            for match in SWITCH.finditer(code):
                begin, end = switch_body(code, match.start())
                if begin is None:
                    continue
                body = top_level(code, begin, end)
                enum = CASE_OF_ENUM.search(body)
                default = DEFAULT.search(body)
                if enum and default:
                    problems.append(
                        f"{path}:{line_of(code, begin + default.start())}: `default:` in a switch "
                        f"over {enum.group(1)}; handle every value so -Wswitch names new ones")


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    problems = []
    check_core_layers(root, problems)
    check_switch_defaults(root, problems)
    for problem in problems:
        print(problem)
    if problems:
        print(f"check-structure: {len(problems)} problem(s)")
        return 1
    print("check-structure: core layers and extension switches are clean")
    return 0


if __name__ == "__main__":
    sys.exit(main())
