#!/usr/bin/env python3
"""Writes the project's hostile scene files: tests/adversarial/scenes/<class>/<nnn>_<name>.toml.

Each file starts with a header the test (tests/adversarial_scenes.rs) reads:

    # class: <class>            what the file attacks (issue 33 item 8's classes)
    # why: <sentence>           the attack
    # command: run|check|linearize|sweep   (default run)
    # args: <extra arguments>   (optional; `{out}` is the output folder)
    # expect: ok | refused at <item path> | refused | refused by <argument> | stopped

`refused at PATH` means exit code 1, a `file:line:col:` location whose line holds the path's
last key (or, for an array element, the key of its array), and PATH named in the message;
`refused` means exit 1 with a location (syntax errors, which have no item path); `refused by
ARG` means exit 1 with a message naming the command-line argument ARG; `stopped`
means exit 1 with the run's rows written and `"complete": false`; `ok` means exit 0.

Run once to (re)write the files: python3 scripts/adversarial_scenes.py
The files are committed; the script is how they were made, not part of the test.
"""
import os
import shutil

ROOT = os.path.join(os.path.dirname(__file__), "..", "tests", "adversarial", "scenes")

PENDULUM = """name = "pendulum"
duration = 1.0
samples = 20
outputs = ["q", "energy"]
checks = ["energy"]

[[bodies]]
name = "rod"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
mass = { shape = "rod", mass = 1.0, length = 1.0 }
com = [0.5, 0.0, 0.0]
q = [0.3]
v = [0.0]

[[effects]]
type = "uniform_gravity"
g = [0.0, -9.81, 0.0]
"""

BALL = """name = "ball"
duration = 2.0
samples = 40
outputs = ["position:ball"]

[[bodies]]
name = "ball"
joint = { type = "free" }
mass = { shape = "sphere", mass = 1.0, radius = 0.1 }
q = [0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0]

[[effects]]
type = "uniform_gravity"
g = [0.0, -9.81, 0.0]

[[effects]]
type = "contact_plane"
body = "ball"
radius = 0.1
normal = [0.0, 1.0, 0.0]
restitution = 0.5
"""

FOUR_BAR = """name = "four_bar"
duration = 1.0
samples = 20
assemble = true
outputs = ["coordinates:rocker", "reaction:coupler_rocker"]

[[bodies]]
name = "crank"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
mass = { shape = "rod", mass = 1.0, length = 1.0 }
com = [0.5, 0.0, 0.0]
q = [0.3]
v = [6.0]

[[bodies]]
name = "coupler"
parent = "crank"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
offset = [1.0, 0.0, 0.0]
mass = { shape = "rod", mass = 1.0, length = 3.5 }
com = [1.75, 0.0, 0.0]
q = [0.68]

[[bodies]]
name = "rocker"
joint = { type = "pin", axis = [0.0, 0.0, 1.0] }
offset = [4.0, 0.0, 0.0]
mass = { shape = "rod", mass = 1.0, length = 3.0 }
com = [1.5, 0.0, 0.0]
q = [1.8]

[[loops]]
type = "pin"
name = "coupler_rocker"
a = { body = "coupler", point = [3.5, 0.0, 0.0] }
b = { body = "rocker", point = [3.0, 0.0, 0.0] }
axis = [0.0, 0.0, 1.0]

[[effects]]
type = "uniform_gravity"
g = [0.0, -9.81, 0.0]
"""

JET = """name = "jet"
duration = 2.0
samples = 20
outputs = ["air:jet", "euler321:jet"]
trim = { free = ["dq:jet.4", "effects[1].elevator", "effects[2]"] }

[[bodies]]
name = "jet"
joint = { type = "free" }
mass = { shape = "aircraft", model = "business_jet" }
v = ["400 kt", 0.0, 0.0, 0.0, 0.0, 0.0]

[[effects]]
type = "uniform_gravity"
g = [0.0, 0.0, "32.2 ft/s^2"]

[[effects]]
type = "aero"
body = "jet"
aircraft = "business_jet"
elevator = { kind = "doublet", start = 0.5, width = 0.5, amplitude = "1 deg" }

[[effects]]
type = "thrust"
body = "jet"
profile = { kind = "constant", value = 0.0 }
"""

CASES = []


def case(cls, name, why, base, edits, expect, command="run", args=""):
    """edits: list of (old, new) replacements applied once each (each must match)."""
    text = base
    for old, new in edits:
        assert old in text, (name, old)
        text = text.replace(old, new, 1)
    CASES.append((cls, name, why, text, expect, command, args))


def numbers():
    c = "hostile_numbers"
    m = "mass = { shape = \"rod\", mass = 1.0, length = 1.0 }"
    for tag, v in [("negative", "-1.0"), ("zero", "0.0"), ("nan", "nan"), ("inf", "inf"), ("huge", "1e155")]:
        case(c, f"mass_{tag}", f"a rod of mass {v}", PENDULUM,
             [(m, m.replace("mass = 1.0", f"mass = {v}"))], "refused at bodies[0].mass.mass")
    for tag, v in [("zero", "0.0"), ("negative", "-1.0"), ("nan", "nan"), ("huge", "1e300")]:
        case(c, f"duration_{tag}", f"duration = {v}", PENDULUM,
             [("duration = 1.0", f"duration = {v}")], "refused at duration")
    case(c, "samples_zero", "no samples", PENDULUM, [("samples = 20", "samples = 0")], "refused at samples")
    case(c, "samples_huge", "a billion samples", PENDULUM, [("samples = 20", "samples = 1000000000")],
         "refused at samples")
    case(c, "samples_negative", "a negative count", PENDULUM, [("samples = 20", "samples = -3")],
         "refused at samples")
    case(c, "samples_float", "a fractional count", PENDULUM, [("samples = 20", "samples = 2.5")],
         "refused at samples")
    for tag, v in [("nan", "nan"), ("overflow", "1e308"), ("huge", "1e151")]:
        case(c, f"q_{tag}", f"an angle of {v}", PENDULUM, [("q = [0.3]", f"q = [{v}]")], "refused at bodies[0].q[0]")
    case(c, "v_inf", "an infinite speed", PENDULUM, [("v = [0.0]", "v = [-inf]")], "refused at bodies[0].v[0]")
    case(c, "q_too_long", "two coordinates for a pin", PENDULUM, [("q = [0.3]", "q = [0.3, 0.1]")],
         "refused at bodies[0].q")
    case(c, "axis_zero", "a zero pin axis", PENDULUM,
         [("axis = [0.0, 0.0, 1.0]", "axis = [0.0, 0.0, 0.0]")], "refused at bodies[0].joint.axis")
    case(c, "axis_nan", "a NaN axis component", PENDULUM,
         [("axis = [0.0, 0.0, 1.0]", "axis = [nan, 0.0, 1.0]")], "refused at bodies[0].joint.axis[0]")
    case(c, "com_huge", "a centre of mass 1e200 m away", PENDULUM,
         [("com = [0.5, 0.0, 0.0]", "com = [1e200, 0.0, 0.0]")], "refused at bodies[0].com[0]")
    case(c, "length_zero", "a rod of length 0", PENDULUM,
         [("length = 1.0", "length = 0.0")], "refused at bodies[0].mass.length")
    case(c, "gravity_huge", "g = -1e308", PENDULUM, [("g = [0.0, -9.81, 0.0]", "g = [0.0, -1e308, 0.0]")],
         "refused at effects[0].g[1]")
    for tag, v in [("zero", "0.0"), ("negative", "-1e-9"), ("nan", "nan"), ("one", "1.0"), ("above_one", "2.0")]:
        case(c, f"accuracy_{tag}", f"accuracy = {v}", PENDULUM, [("samples = 20", f"samples = 20\naccuracy = {v}")],
             "refused at accuracy")
    case(c, "accuracy_loose", "accuracy = 0.5: the loosest method, and the energy check says how good", PENDULUM,
         [("samples = 20", "samples = 20\naccuracy = 0.5")], "ok")
    case(c, "max_steps_zero", "no steps allowed", PENDULUM, [("samples = 20", "samples = 20\nmax_steps = 0")],
         "refused at max_steps")
    case(c, "max_wall_negative", "a negative wall budget", PENDULUM,
         [("samples = 20", "samples = 20\nmax_wall_seconds = -1.0")], "refused at max_wall_seconds")
    case(c, "max_steps_tiny", "a step budget far too small: the run stops and says so", PENDULUM,
         [("samples = 20", "samples = 20\nmax_steps = 2\naccuracy = 1e-10"), ("duration = 1.0", "duration = 100.0")],
         "stopped")
    case(c, "profile_corner_subnormal", "a step profile 1e-300 s after t = 0", PENDULUM,
         [("[[effects]]", "[[effects]]\ntype = \"torque\"\nbody = \"rod\"\ndirection = [0.0, 0.0, 1.0]\n"
           "profile = { kind = \"step\", at = 1e-300, after = 1.0 }\n\n[[effects]]")],
         "refused at effects[0].profile.at")


def quantities():
    c = "quantity_strings"
    m = "mass = { shape = \"rod\", mass = 1.0, length = 1.0 }"
    for tag, v in [("wrong_dimension", "\"1 m\""), ("not_a_quantity", "\"abc\""), ("unknown_unit", "\"1 kgg\""),
                   ("overflow", "\"1e999 kg\""), ("empty", "\"\""), ("double_unit", "\"1 kg kg\""),
                   ("nan", "\"nan kg\""), ("huge", "\"1e200 kg\"")]:
        case(c, f"mass_{tag}", f"mass = {v}", PENDULUM, [(m, m.replace("mass = 1.0", f"mass = {v}"))],
             "refused at bodies[0].mass.mass")
    case(c, "angle_as_length", "q = [\"30 m\"] for a pin", PENDULUM, [("q = [0.3]", "q = [\"30 m\"]")],
         "refused at bodies[0].q[0]")
    case(c, "angle_in_degrees", "q = [\"30 deg\"] is fine", PENDULUM, [("q = [0.3]", "q = [\"30 deg\"]")], "ok")
    case(c, "gravity_as_speed", "g in m/s", PENDULUM, [("g = [0.0, -9.81, 0.0]", "g = [0.0, \"-9.81 m/s\", 0.0]")],
         "refused at effects[0].g[1]")
    case(c, "duration_in_kg", "duration = \"1 kg\"", PENDULUM, [("duration = 1.0", "duration = \"1 kg\"")],
         "refused at duration")
    case(c, "duration_in_minutes", "duration = \"0.5 min\" is fine", PENDULUM,
         [("duration = 1.0", "duration = \"0.02 min\"")], "ok")
    case(c, "negative_length", "length = \"-1 m\"", PENDULUM, [("length = 1.0", "length = \"-1 m\"")],
         "refused at bodies[0].mass.length")
    case(c, "samples_as_quantity", "samples = \"10 s\"", PENDULUM, [("samples = 20", "samples = \"10 s\"")],
         "refused at samples")
    case(c, "speed_in_knots", "the jet's speed in knots, gravity in ft/s²", JET, [], "ok")
    case(c, "speed_as_angle", "a speed in degrees", JET, [("v = [\"400 kt\"", "v = [\"400 deg\"")],
         "refused at bodies[0].v[0]")


def structure():
    c = "structure"
    case(c, "unknown_top_key", "durration", PENDULUM, [("duration = 1.0", "durration = 1.0")], "refused at durration")
    case(c, "unknown_inline_key", "axs inside an inline table", PENDULUM,
         [("axis = [0.0, 0.0, 1.0]", "axs = [0.0, 0.0, 1.0]")], "refused at bodies[0].joint.axs")
    case(c, "missing_name", "no name", PENDULUM, [("name = \"pendulum\"\n", "")], "refused")
    case(c, "missing_bodies", "no bodies", "name = \"x\"\nduration = 1.0\n", [], "refused")
    case(c, "empty_bodies", "bodies = []", "name = \"x\"\nduration = 1.0\nbodies = []\n", [], "refused at bodies")
    case(c, "duplicate_body", "two bodies named rod", PENDULUM,
         [("[[effects]]", "[[bodies]]\nname = \"rod\"\njoint = { type = \"pin\", axis = [0.0, 0.0, 1.0] }\n"
           "mass = { shape = \"particle\", mass = 1.0 }\n\n[[effects]]")], "refused at bodies[1].name")
    case(c, "unknown_parent", "parent = nobody", PENDULUM, [("name = \"rod\"\n", "name = \"rod\"\nparent = \"nobody\"\n")],
         "refused at bodies[0].parent")
    case(c, "self_parent", "a body that is its own parent", PENDULUM,
         [("name = \"rod\"\n", "name = \"rod\"\nparent = \"rod\"\n")], "refused at bodies[0].parent")
    case(c, "parent_cycle", "crank → coupler → crank", FOUR_BAR,
         [("name = \"crank\"\n", "name = \"crank\"\nparent = \"coupler\"\n")], "refused at bodies[0].parent")
    case(c, "unknown_joint", "a hinge joint", PENDULUM, [("type = \"pin\"", "type = \"hinge\"")],
         "refused at bodies[0].joint.type")
    case(c, "unknown_shape", "a cone", PENDULUM, [("shape = \"rod\"", "shape = \"cone\"")],
         "refused at bodies[0].mass.shape")
    case(c, "duplicate_key", "duration twice", PENDULUM, [("duration = 1.0", "duration = 1.0\nduration = 2.0")],
         "refused")
    case(c, "syntax_error", "an unclosed array", PENDULUM, [("q = [0.3]", "q = [0.3")], "refused")
    case(c, "wrong_type", "a string for a number list", PENDULUM, [("q = [0.3]", "q = \"0.3\"")],
         "refused at bodies[0].q")
    case(c, "unknown_output", "outputs = [qq]", PENDULUM, [("outputs = [\"q\", \"energy\"]", "outputs = [\"qq\"]")],
         "refused at outputs[0]")
    case(c, "repeated_output", "the same output twice", PENDULUM,
         [("outputs = [\"q\", \"energy\"]", "outputs = [\"q\", \"q\"]")], "refused at outputs[1]")
    case(c, "output_unknown_body", "position:nobody", PENDULUM,
         [("outputs = [\"q\", \"energy\"]", "outputs = [\"position:nobody\"]")], "refused at outputs[0]")
    case(c, "unknown_check", "checks = [momentum2]", PENDULUM, [("checks = [\"energy\"]", "checks = [\"momentum2\"]")],
         "refused at checks[0]")
    case(c, "unknown_effect", "an effect of type wind", PENDULUM,
         [("type = \"uniform_gravity\"", "type = \"wind\"")], "refused at effects[0].type")
    case(c, "massless_leaf", "a massless body carrying nothing", PENDULUM,
         [("shape = \"rod\", mass = 1.0, length = 1.0", "shape = \"massless\"")], "refused at bodies[0].mass")


def output_safety():
    c = "output_safety"
    for tag, v in [("parent_dir", "../escape"), ("absolute", "/tmp/evil"), ("slash", "a/b"), ("dot", "."),
                   ("dotdot", ".."), ("empty", ""), ("long", "x" * 300), ("control", "a\\u0007b"),
                   ("script", "</script><script>alert(1)</script>")]:
        case(c, f"name_{tag}", f"a scene named {v[:40]!r}", PENDULUM,
             [("name = \"pendulum\"", f"name = \"{v}\"")], "refused at name")
    case(c, "outputs_repeated_many", "2000 outputs (the same one repeated)", PENDULUM,
         [("outputs = [\"q\", \"energy\"]", "outputs = [" + ", ".join(["\"q\""] * 2000) + "]")],
         "refused at outputs[1]")
    case(c, "budget_too_small", "a run whose files exceed --max-output-bytes: refused before writing", PENDULUM,
         [("samples = 20", "samples = 100000")], "refused", args="--max-output-bytes 10000")
    case(c, "ordinary_run", "a plain run writes only into --out", PENDULUM, [], "ok")


def loops():
    c = "loops"
    case(c, "unknown_body", "a loop to a body that does not exist", FOUR_BAR,
         [("b = { body = \"rocker\"", "b = { body = \"rocket\"")], "refused at loops[0].b.body")
    case(c, "both_ground", "a loop from the ground to the ground", FOUR_BAR,
         [("a = { body = \"coupler\"", "a = { body = \"ground\""), ("b = { body = \"rocker\"", "b = { body = \"ground\"")],
         "refused at loops[0].a.body")
    case(c, "same_body", "a loop from a body to itself", FOUR_BAR,
         [("b = { body = \"rocker\"", "b = { body = \"coupler\"")], "refused at loops[0].b.body")
    case(c, "zero_axis", "a pin loop with a zero axis", FOUR_BAR,
         [("axis = [0.0, 0.0, 1.0]\n\n[[effects]]", "axis = [0.0, 0.0, 0.0]\n\n[[effects]]")],
         "refused at loops[0].axis")
    case(c, "nan_point", "a NaN attachment point", FOUR_BAR,
         [("point = [3.5, 0.0, 0.0]", "point = [nan, 0.0, 0.0]")], "refused at loops[0].a.point[0]")
    case(c, "unknown_type", "a loop of type weld", FOUR_BAR, [("type = \"pin\"\nname", "type = \"weld\"\nname")],
         "refused at loops[0].type")
    case(c, "unassemblable", "a loop that cannot close (the coupler too short)", FOUR_BAR,
         [("length = 3.5", "length = 0.5"), ("point = [3.5, 0.0, 0.0]", "point = [0.5, 0.0, 0.0]"),
          ("point = [3.0, 0.0, 0.0]", "point = [1.0, 0.0, 0.0]")],
         "refused")
    case(c, "ordinary", "the four-bar runs", FOUR_BAR, [], "ok")
    case(c, "reaction_unknown", "the reaction of a loop that does not exist", FOUR_BAR,
         [("reaction:coupler_rocker", "reaction:nothing")], "refused at outputs[1]")
    case(c, "linearize_refused", "a loop scene linearized (loops are not in the exact right-hand side)", FOUR_BAR,
         [], "refused", command="linearize")


def aircraft():
    c = "aircraft_and_trim"
    case(c, "unknown_aircraft", "a glider", JET, [("aircraft = \"business_jet\"", "aircraft = \"glider\"")],
         "refused at effects[1].aircraft")
    case(c, "unknown_airframe", "mass of a glider", JET, [("model = \"business_jet\"", "model = \"glider\"")],
         "refused at bodies[0].mass.model")
    case(c, "rho_zero", "no air", JET, [("aircraft = \"business_jet\"", "aircraft = \"business_jet\"\nrho = 0.0")],
         "refused at effects[1].rho")
    case(c, "rho_wrong_unit", "ρ in kg", JET,
         [("aircraft = \"business_jet\"", "aircraft = \"business_jet\"\nrho = \"1 kg\"")], "refused at effects[1].rho")
    case(c, "doublet_zero_width", "a doublet of width 0", JET, [("width = 0.5", "width = 0.0")],
         "refused at effects[1].elevator.width")
    case(c, "aero_on_pin", "aero on a body on a pin", PENDULUM,
         [("[[effects]]", "[[effects]]\ntype = \"aero\"\nbody = \"rod\"\naircraft = \"business_jet\"\n\n[[effects]]")],
         "refused at effects[0].body")
    case(c, "thrust_unknown_body", "thrust on a body that does not exist", JET,
         [("type = \"thrust\"\nbody = \"jet\"", "type = \"thrust\"\nbody = \"jett\"")], "refused at effects[2].body")
    case(c, "at_rest", "an aircraft at rest (α undefined)", JET, [("v = [\"400 kt\"", "v = [0.0"),
                                                                   ("trim = {", "# trim = {")], "refused")
    case(c, "trim_unknown", "trim an unknown state", JET, [("\"dq:jet.4\"", "\"dq:jet.9\"")], "refused at trim.free[0]")
    case(c, "trim_empty", "trim with no unknowns", JET,
         [("trim = { free = [\"dq:jet.4\", \"effects[1].elevator\", \"effects[2]\"] }", "trim = { free = [] }")],
         "refused at trim.free")
    case(c, "trim_twice", "the same unknown twice", JET, [("\"effects[2]\"]", "\"effects[2]\", \"effects[2]\"]")],
         "refused at trim.free[3]")
    case(c, "trim_hold_unknown", "hold a column that is not an output", JET,
         [("\"effects[2]\"] }", "\"effects[2]\"], hold = { \"air:jet.gamma\" = 0.0 } }")], "refused at trim.hold")
    case(c, "trim_impossible", "trim without the thrust: drag cannot be balanced", JET,
         [("\"effects[1].elevator\", \"effects[2]\"]", "\"effects[1].elevator\"]")], "refused at trim.free")
    case(c, "jet_runs", "the trimmed jet flies a doublet", JET, [], "ok")
    case(c, "jet_linearizes", "the trimmed jet linearizes (steady)", JET,
         [("trim = {", "linearize = { steady = true }\ntrim = {")], "ok", command="linearize")


def sweeps():
    c = "sweep"
    case(c, "repeated_param", "--param duration twice", PENDULUM, [], "refused by --param",
         command="sweep", args="--param duration=1,2 --param duration=3")
    case(c, "param_not_number", "--param duration=abc", PENDULUM, [], "refused by --param", command="sweep",
         args="--param duration=abc")
    case(c, "param_unknown", "--param nokey=1", PENDULUM, [], "refused by nokey", command="sweep",
         args="--param nokey=1")
    case(c, "param_invalid_value", "--param duration=-1 (each run validated)", PENDULUM, [], "refused",
         command="sweep", args="--param duration=-1")
    case(c, "ordinary", "a two-point sweep", PENDULUM, [], "ok", command="sweep", args="--param duration=0.5,1")


def linearize():
    c = "linearize"
    case(c, "pendulum", "the pendulum about its hanging equilibrium", PENDULUM, [("q = [0.3]", "q = [0.0]")], "ok",
         command="linearize")
    case(c, "not_equilibrium", "a pendulum away from equilibrium: linearized with the residual reported",
         PENDULUM, [], "ok", command="linearize")
    case(c, "steady_not_cyclic", "steady = true for a swinging pendulum", PENDULUM,
         [("v = [0.0]", "v = [1.0]"), ("samples = 20", "samples = 20\nlinearize = { steady = true }")],
         "refused at linearize.steady", command="linearize")
    case(c, "contacts", "a bouncing ball linearized", BALL, [], "ok", command="linearize")
    case(c, "inerter", "an inerter is not in the exact right-hand side", PENDULUM,
         [("[[effects]]", "[[effects]]\ntype = \"rotational_inerter\"\nbody = \"rod\"\nbeta = 0.1\n\n[[effects]]")],
         "refused at effects", command="linearize")


def contacts():
    c = "contacts"
    for tag, v in [("above_one", "1.5"), ("negative", "-0.1"), ("nan", "nan")]:
        case(c, f"restitution_{tag}", f"restitution = {v}", BALL, [("restitution = 0.5", f"restitution = {v}")],
             "refused at effects[1].restitution")
    case(c, "friction_negative", "friction = -1", BALL, [("restitution = 0.5", "restitution = 0.5\nfriction = -1.0")],
         "refused at effects[1].friction")
    case(c, "radius_zero", "radius 0: a point bouncing on the floor", BALL,
         [("radius = 0.1\nnormal", "radius = 0.0\nnormal")], "ok")
    case(c, "radius_negative", "radius -0.1", BALL, [("radius = 0.1\nnormal", "radius = -0.1\nnormal")],
         "refused at effects[1].radius")
    case(c, "normal_zero", "a zero normal", BALL, [("normal = [0.0, 1.0, 0.0]", "normal = [0.0, 0.0, 0.0]")],
         "refused at effects[1].normal")
    case(c, "on_pin", "a contact on a body on a pin", PENDULUM,
         [("[[effects]]", "[[effects]]\ntype = \"contact_plane\"\nbody = \"rod\"\nradius = 0.1\n"
           "normal = [0.0, 1.0, 0.0]\nrestitution = 0.5\n\n[[effects]]")], "refused at effects[0].body")
    case(c, "starts_inside", "the ball starts below the floor", BALL,
         [("q = [0.0, 1.0, 0.0", "q = [0.0, -1.0, 0.0")], "refused")
    case(c, "spheres_same_body", "a sphere colliding with itself", BALL,
         [("type = \"contact_plane\"\nbody = \"ball\"\nradius = 0.1\nnormal = [0.0, 1.0, 0.0]",
           "type = \"contact_spheres\"\na = \"ball\"\nb = \"ball\"\nradius_a = 0.1\nradius_b = 0.1")],
         "refused at effects[1].b")
    case(c, "bounces_to_rest", "e = 0.5 bounces, comes to rest, and stays on the floor", BALL,
         [("duration = 2.0", "duration = 5.0")], "ok")
    case(c, "elastic_many", "e = 1 for 10 s: every bounce found", BALL,
         [("duration = 2.0", "duration = 10.0"), ("restitution = 0.5", "restitution = 1.0")], "ok")


def main():
    for f in [numbers, quantities, structure, output_safety, loops, aircraft, sweeps, linearize, contacts]:
        f()
    if os.path.isdir(ROOT):
        shutil.rmtree(ROOT)
    for n, (cls, name, why, text, expect, command, args) in enumerate(CASES):
        d = os.path.join(ROOT, cls)
        os.makedirs(d, exist_ok=True)
        head = f"# class: {cls}\n# why: {why}\n# command: {command}\n"
        if args:
            head += f"# args: {args}\n"
        head += f"# expect: {expect}\n"
        with open(os.path.join(d, f"{n:03d}_{name}.toml"), "w") as fh:
            fh.write(head + text)
    # invalid UTF-8 inside a string: refused with the byte's line and column
    d = os.path.join(ROOT, "structure")
    head = "# class: structure\n# why: invalid UTF-8 in the name\n# command: run\n# expect: refused\n"
    body = PENDULUM.replace('name = "pendulum"', 'name = "pend\xffulum"').encode("utf-8")
    body = body.replace("\xff".encode("utf-8"), b"\xff")
    with open(os.path.join(d, f"{len(CASES):03d}_invalid_utf8.toml"), "wb") as fh:
        fh.write(head.encode() + body)
    print(f"{len(CASES) + 1} files under {os.path.normpath(ROOT)}")


if __name__ == "__main__":
    main()
