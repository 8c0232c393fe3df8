# Shared by the .cfg files of this directory: builds a dynamic_reconfigure description of one
# section of live parameters from cfg/live_parameters.yaml (generated from the core's parameter
# schema), so no parameter is listed by hand. A section's server runs in the section's namespace
# (~symmetry/filter for "symmetry.filter"), so each live parameter keeps its one nested name.
import os
import sys

import yaml
from dynamic_reconfigure.parameter_generator_catkin import ParameterGenerator, bool_t, double_t, int_t

PACKAGE = "symmetry_segmentation"
LIVE_PARAMETERS = os.path.join(os.path.dirname(os.path.realpath(__file__)), "live_parameters.yaml")
TYPES = {"float": double_t, "int": int_t, "bool": bool_t}


def live_parameters(section):
    """The entries of live_parameters.yaml whose key is `section`.<name>."""
    with open(LIVE_PARAMETERS) as stream:
        entries = yaml.safe_load(stream) or []
    return [entry for entry in entries if entry["key"].rpartition(".")[0] == section]


def description(entry):
    # dynamic_reconfigure rejects quotes in descriptions.
    text = "%s: %s" % (entry["key"], entry["doc"])
    if entry.get("unit"):
        text += " (%s)" % entry["unit"]
    return text.replace('"', "").replace("'", "")


def generate(section, name):
    """Writes the <name>Config type for the live parameters of `section` and exits."""
    entries = live_parameters(section)
    if not entries:
        sys.exit("%s: no live parameter in section '%s' of %s" % (name, section, LIVE_PARAMETERS))
    gen = ParameterGenerator()
    for entry in entries:
        if entry["type"] not in TYPES:
            sys.exit("%s: live parameter %s has type %s, which dynamic_reconfigure cannot hold"
                     % (name, entry["key"], entry["type"]))
        leaf = entry["key"].rpartition(".")[2]
        if entry["type"] == "bool":
            gen.add(leaf, bool_t, 0, description(entry), bool(entry["default"]))
        else:
            cast = float if entry["type"] == "float" else int
            gen.add(leaf, TYPES[entry["type"]], 0, description(entry), cast(entry["default"]),
                    cast(entry["min"]), cast(entry["max"]))
    sys.exit(gen.generate(PACKAGE, PACKAGE, name))
