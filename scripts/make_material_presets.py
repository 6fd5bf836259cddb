#!/usr/bin/env python3
"""Writes presets/materials/*.json: the measured fabrics of Wang, Ramamoorthi & O'Brien 2011 in
Weft's material format, plus a few isotropic materials defined below.

The measured numbers are copied as text (the exact tokens of the source files), so the presets hold
the same values, negative samples included; Weft's material model clamps them when it evaluates.
The format is described in presets/materials/README.md.

Usage: python3 scripts/make_material_presets.py [--data DIR] [--out DIR]
  --data  the Wang 2011 files and their FORMAT.md (default: ../shared/data/wang2011 beside the repo)
  --out   where the presets go (default: presets/materials in the repo)
"""
import argparse
import json
import pathlib
import re
import sys

REPO = pathlib.Path(__file__).resolve().parent.parent
SOURCE_TEMPLATE = (
    "Wang, Ramamoorthi & O'Brien 2011, 'Data-Driven Elastic Models for Cloth', measured fabric {name} "
    "({garment}, {fibres}), as distributed with ARCSim 0.3.1; values unchanged"
)
REFERENCE_STRETCH = 7.0 / 6.0  # ARCSim's strain coordinate 6*(lambda - 1) reaches 1 at lambda = 7/6

# Isotropic materials: not measurements; each source string says where its numbers come from.
ISOTROPIC = [
    {
        "name": "isotropic-cotton",
        "source": (
            "Weft isotropic stand-in for a woven cotton: E*h = 4000 N/m, close to royal-target's (65% cotton) "
            "small-strain warp and weft membrane stiffness 2*c11, 2*c22 (4033, 4070 N/m); "
            "nu = 0.3 is a conventional value, not measured; area density and bending stiffness are "
            "royal-target's (density 0.220 kg/m^2; median of its measured bending samples, 1.67e-4 N*m, rounded to 1.7e-4)"
        ),
        "area_density_kg_m2": 0.22,
        "elasticity": {"model": "isotropic", "young_modulus_n_per_m": 4000.0, "poisson_ratio": 0.3},
        "bending": {"model": "constant", "stiffness_n_m": 1.7e-4},
    },
    {
        "name": "isotropic-stiff",
        "source": (
            "Weft isotropic test material, not a measured fabric: a stiff, nearly inextensible sheet "
            "with E*h = 1e5 N/m (25 times isotropic-cotton), nu = 0.3, area density 0.2 kg/m^2 and "
            "bending stiffness 1e-3 N*m, for tests and scenes that need small stretch"
        ),
        "area_density_kg_m2": 0.2,
        "elasticity": {"model": "isotropic", "young_modulus_n_per_m": 100000.0, "poisson_ratio": 0.3},
        "bending": {"model": "constant", "stiffness_n_m": 1e-3},
    },
]


class Number:
    """A number kept as the exact token it was read from."""

    def __init__(self, text):
        self.text = text

    def __float__(self):
        return float(self.text)


def read_catalogue(format_md):
    """Rows of FORMAT.md's table: file -> (garment, fibres, density)."""
    rows = {}
    pattern = re.compile(r"^\|\s*([\w-]+)\.json\s*\|([^|]*)\|([^|]*)\|\s*([0-9.]+)\s*\|\s*$")
    for line in format_md.read_text().splitlines():
        match = pattern.match(line)
        if match:
            garment = re.sub(r"\s*\(.*\)", "", match.group(2)).strip()  # "jeans (thesis: denim)" -> "jeans"
            rows[match.group(1)] = (garment, match.group(3).strip(), float(match.group(4)))
    return rows


def read_source(path):
    data = json.loads(path.read_text(), parse_float=Number, parse_int=Number)
    if set(data) != {"density", "stretching", "bending"}:
        sys.exit(f"{path}: expected exactly the keys density, stretching, bending, got {sorted(data)}")
    shapes = {"stretching": (6, 4), "bending": (3, 5)}
    for key, (rows, cols) in shapes.items():
        table = data[key]
        if len(table) != rows or any(len(row) != cols for row in table):
            sys.exit(f"{path}: {key} must be {rows} rows of {cols} numbers")
    return data


def measured_preset(name, data, garment, fibres):
    stretching = data["stretching"]
    return {
        "name": name,
        "source": SOURCE_TEMPLATE.format(name=name, garment=garment, fibres=fibres),
        "area_density_kg_m2": data["density"],
        "elasticity": {
            "model": "measured",
            "units": "N/m",
            "coefficients": ["c11", "c12", "c22", "c33"],
            "zero_strain": stretching[0],
            "direction_deg": [0, 22.5, 45, 67.5, 90],
            "at_reference_stretch": stretching[1:],
            "reference_stretch": REFERENCE_STRETCH,
        },
        "bending": {
            "model": "measured",
            "units": "N*m",
            "edge_direction_deg": [0, 45, 90],
            "curvature_alpha_per_m": [0, 5, 10, 15, 20],
            "stiffness": data["bending"],
        },
    }


def is_scalar(value):
    return not isinstance(value, (dict, list))


def to_text(value, indent=0):
    """JSON with one line per object member and per table row, numbers as read."""
    pad = "  " * (indent + 1)
    if isinstance(value, Number):
        return value.text
    if isinstance(value, dict):
        members = [f"{pad}{json.dumps(key)}: {to_text(item, indent + 1)}" for key, item in value.items()]
        return "{\n" + ",\n".join(members) + "\n" + "  " * indent + "}"
    if isinstance(value, list):
        if all(is_scalar(item) for item in value):
            return "[" + ", ".join(to_text(item) for item in value) + "]"
        rows = [pad + to_text(item, indent + 1) for item in value]
        return "[\n" + ",\n".join(rows) + "\n" + "  " * indent + "]"
    return json.dumps(value)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", type=pathlib.Path, default=REPO.parent / "shared" / "data" / "wang2011")
    parser.add_argument("--out", type=pathlib.Path, default=REPO / "presets" / "materials")
    args = parser.parse_args()

    catalogue = read_catalogue(args.data / "FORMAT.md")
    sources = sorted(args.data.glob("*.json"))
    if {path.stem for path in sources} != set(catalogue):
        sys.exit(f"FORMAT.md's table and the .json files in {args.data} disagree")

    presets = []
    for path in sources:
        data = read_source(path)
        garment, fibres, density = catalogue[path.stem]
        if float(data["density"]) != density:
            sys.exit(f"{path}: density {data['density'].text} differs from FORMAT.md's {density}")
        presets.append(measured_preset(path.stem, data, garment, fibres))
    presets += ISOTROPIC

    args.out.mkdir(parents=True, exist_ok=True)
    for preset in presets:
        target = args.out / (preset["name"] + ".json")
        target.write_text(to_text(preset) + "\n")
        json.loads(target.read_text())  # what we wrote must be plain JSON
        print(f"wrote {target}")


if __name__ == "__main__":
    main()
