#!/usr/bin/env python3
"""Writes the model gallery examples/models/*.urdf|*.xml (issue 35): models written for
vectrix, not third-party files. Deterministic: run again, get the same bytes.

    python3 scripts/make_models.py

Book: §7.11 (trees), §1.5 (joints); the four-bar, double pendulum and top of ch. 7-9.
"""
import math
import os

OUT = os.path.join(os.path.dirname(__file__), "..", "examples", "models")


def inertia_xml(m, xyz, rpy, ixx, iyy, izz, ixy=0.0, ixz=0.0, iyz=0.0):
    return (
        f'    <inertial>\n      <origin xyz="{xyz}" rpy="{rpy}"/>\n      <mass value="{m}"/>\n'
        f'      <inertia ixx="{ixx}" ixy="{ixy}" ixz="{ixz}" iyy="{iyy}" iyz="{iyz}" izz="{izz}"/>\n'
        f"    </inertial>\n"
    )


def arm7():
    """A 7-DOF arm: axes z y z y z y x, joint frames turned by rpy, inertials offset and
    turned, full inertia tensors, a fixed tool merged into the last link, a visual mesh."""
    axes = ["0 0 1", "0 1 0", "0 0 1", "0 1 0", "0 0 1", "0 1 0", "1 0 0"]
    s = '<?xml version="1.0"?>\n<robot name="arm7">\n  <link name="base">\n'
    s += inertia_xml(4.0, "0 0 0.05", "0 0 0", 0.02, 0.02, 0.03)
    s += '    <visual><geometry><mesh filename="package://arm7/meshes/base.stl"/></geometry></visual>\n  </link>\n'
    parent = "base"
    for k in range(7):
        name = f"link{k + 1}"
        m = 3.0 - 0.3 * k
        s += f'  <link name="{name}">\n'
        s += inertia_xml(
            round(m, 3),
            f"{0.01 * k} {-0.02 + 0.005 * k} {0.12 - 0.01 * k}",
            f"{0.1 * k} {-0.05 * k} {0.2}",
            round(0.03 - 0.002 * k, 6), round(0.025 - 0.002 * k, 6), round(0.012 - 0.001 * k, 6),
            ixy=0.001, ixz=-0.0005 * (k % 3), iyz=0.0007,
        )
        s += '    <collision><geometry><cylinder radius="0.05" length="0.2"/></geometry></collision>\n  </link>\n'
        xyz = f"{0.02 * (k % 2)} 0 {0.25 - 0.02 * k}"
        rpy = f"{0.3 if k % 2 else 0} {-0.2 if k % 3 == 1 else 0} {0.15 * k}"
        s += (
            f'  <joint name="joint{k + 1}" type="revolute">\n    <parent link="{parent}"/>\n'
            f'    <child link="{name}"/>\n    <origin xyz="{xyz}" rpy="{rpy}"/>\n'
            f'    <axis xyz="{axes[k]}"/>\n    <limit lower="-2.9" upper="2.9" effort="80" velocity="2.5"/>\n'
            f'    <dynamics damping="0.1"/>\n  </joint>\n'
        )
        parent = name
    s += '  <link name="tool">\n' + inertia_xml(0.5, "0 0 0.04", "0.3 0 0", 0.001, 0.002, 0.0015) + "  </link>\n"
    s += (
        '  <joint name="tool_mount" type="fixed">\n    <parent link="link7"/>\n    <child link="tool"/>\n'
        '    <origin xyz="0.01 0 0.1" rpy="0 0.5 0"/>\n  </joint>\n</robot>\n'
    )
    return s


def quadruped():
    """A floating base with four 3-joint legs (hip roll about x, hip pitch about y, knee about
    y) and feet merged through fixed joints."""
    s = '<?xml version="1.0"?>\n<robot name="quadruped">\n  <link name="world"/>\n'
    s += '  <joint name="base_free" type="floating">\n    <parent link="world"/>\n    <child link="trunk"/>\n    <origin xyz="0 0 0.45"/>\n  </joint>\n'
    s += '  <link name="trunk">\n' + inertia_xml(12.0, "0.01 0 0", "0 0 0", 0.06, 0.25, 0.28, ixy=0.001) + "  </link>\n"
    for leg, (sx, sy) in {"fl": (1, 1), "fr": (1, -1), "hl": (-1, 1), "hr": (-1, -1)}.items():
        chain = [
            ("hip", "1 0 0", f"{0.19 * sx} {0.05 * sy} 0", "0 0 0", (1.0, f"0 {0.03 * sy} 0", 0.0008, 0.001, 0.0009)),
            ("thigh", "0 1 0", f"0 {0.08 * sy} 0", "0 0 0", (1.2, "0 0 -0.03", 0.006, 0.006, 0.0011)),
            ("calf", "0 1 0", "0 0 -0.2", "0 0 0", (0.3, "0 0 -0.1", 0.003, 0.003, 0.0001)),
        ]
        parent = "trunk"
        for part, axis, xyz, rpy, (m, c, ixx, iyy, izz) in chain:
            name = f"{leg}_{part}"
            s += f'  <link name="{name}">\n' + inertia_xml(m, c, "0 0 0", ixx, iyy, izz) + "  </link>\n"
            s += (
                f'  <joint name="{name}_joint" type="revolute">\n    <parent link="{parent}"/>\n    <child link="{name}"/>\n'
                f'    <origin xyz="{xyz}" rpy="{rpy}"/>\n    <axis xyz="{axis}"/>\n'
                f'    <limit lower="-2.5" upper="2.5" effort="33" velocity="21"/>\n  </joint>\n'
            )
            parent = name
        s += f'  <link name="{leg}_foot">\n' + inertia_xml(0.06, "0 0 0", "0 0 0", 1e-5, 1e-5, 1e-5) + "  </link>\n"
        s += (
            f'  <joint name="{leg}_foot_fixed" type="fixed">\n    <parent link="{leg}_calf"/>\n    <child link="{leg}_foot"/>\n'
            f'    <origin xyz="0 0 -0.2"/>\n  </joint>\n'
        )
    return s + "</robot>\n"


def double_pendulum_urdf():
    """The book's double pendulum (§7.11) with thin rods of 1 kg, 1 m, swinging about z in
    the x-y plane (gravity along −y in its scene)."""
    rod = lambda: inertia_xml(1.0, "0 -0.5 0", "0 0 0", 1.0 / 12, 1e-4, 1.0 / 12)
    return (
        '<?xml version="1.0"?>\n<robot name="double_pendulum">\n  <link name="world"/>\n'
        f'  <link name="upper">\n{rod()}  </link>\n  <link name="lower">\n{rod()}  </link>\n'
        '  <joint name="shoulder" type="revolute">\n    <parent link="world"/>\n    <child link="upper"/>\n'
        '    <axis xyz="0 0 1"/>\n    <limit lower="-3.2" upper="3.2" effort="0" velocity="100"/>\n  </joint>\n'
        '  <joint name="elbow" type="revolute">\n    <parent link="upper"/>\n    <child link="lower"/>\n'
        '    <origin xyz="0 -1 0"/>\n    <axis xyz="0 0 1"/>\n    <limit lower="-3.2" upper="3.2" effort="0" velocity="100"/>\n  </joint>\n'
        "</robot>\n"
    )


def double_pendulum_mjcf():
    return """<mujoco model="double_pendulum">
  <compiler angle="radian"/>
  <option gravity="0 -9.81 0" timestep="0.001"/>
  <worldbody>
    <body name="upper">
      <joint name="shoulder" type="hinge" axis="0 0 1"/>
      <geom type="capsule" fromto="0 0 0 0 -1 0" size="0.02" mass="1"/>
      <body name="lower" pos="0 -1 0">
        <joint name="elbow" type="hinge" axis="0 0 1"/>
        <geom type="capsule" fromto="0 0 0 0 -1 0" size="0.02" mass="1"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def top_mjcf():
    """The book's heavy top on a fixed point (§8.x): a ball joint at the tip, J = diag(0.05,
    0.05, 0.1) kg m² about the centre 0.5 m up the axis."""
    return """<mujoco model="top">
  <option gravity="0 0 -9.81"/>
  <worldbody>
    <geom type="plane" size="2 2 0.1"/>
    <body name="top">
      <joint name="tip" type="ball"/>
      <inertial pos="0 0 0.5" mass="1" diaginertia="0.05 0.05 0.1"/>
      <geom type="cylinder" pos="0 0 0.5" size="0.3 0.02" contype="0"/>
    </body>
  </worldbody>
</mujoco>
"""


def fourbar_mjcf():
    """The book's four-bar of examples/scenes/four_bar.toml: crank 1 m, coupler 3.5 m, rocker
    3 m, ground 4 m, thin rods of 1 kg; the coupler–rocker pin is an equality connect."""
    return """<mujoco model="four_bar">
  <compiler angle="radian"/>
  <option gravity="0 -9.81 0"/>
  <default>
    <joint type="hinge" axis="0 0 1"/>
    <default class="rod">
      <geom type="capsule" size="0.01" mass="1" rgba="0.8 0.3 0.2 1"/>
    </default>
  </default>
  <worldbody>
    <body name="crank" euler="0 0 0.3">
      <joint name="crank_pin"/>
      <geom class="rod" fromto="0 0 0 1 0 0"/>
      <body name="coupler" pos="1 0 0" euler="0 0 0.68">
        <joint name="coupler_pin"/>
        <geom class="rod" fromto="0 0 0 3.5 0 0"/>
      </body>
    </body>
    <body name="rocker" pos="4 0 0" euler="0 0 1.8">
      <joint name="rocker_pin"/>
      <geom class="rod" fromto="0 0 0 3 0 0"/>
    </body>
  </worldbody>
  <equality>
    <connect name="coupler_rocker" body1="coupler" body2="rocker" anchor="3.5 0 0"/>
  </equality>
</mujoco>
"""


def humanoid_mjcf():
    """A humanoid-like tree: a free torso, spine (2 hinges in one body), neck (ball), two
    arms of 7 joints and two legs of 6 joints, with geom-derived and stated inertias, default
    classes, degrees, joints off the body origin: 6 + 34 degrees of freedom."""
    def limb(side, sy, arm):
        ind = "      "
        if arm:
            segs = [
                ("shoulder", f"0 {0.2 * sy} 0.25", ["x", "y", "z"], "0 0 0 0 0 -0.28", 0.04),
                ("elbow", "0 0 -0.3", ["y"], "0 0 0 0 0 -0.25", 0.035),
                ("wrist", "0 0 -0.27", ["z", "x", "y"], "0 0 0 0 0 -0.08", 0.03),
            ]
        else:
            segs = [
                ("hip", f"0 {0.1 * sy} -0.25", ["x", "y", "z"], "0 0 0 0 0 -0.4", 0.06),
                ("knee", "0 0 -0.42", ["y"], "0 0 0 0 0 -0.4", 0.05),
                ("ankle", "0 0 -0.42", ["y", "x"], "0 0 0 0.12 0 -0.04", 0.04),
            ]
        s, close = "", ""
        for k, (seg, pos, jaxes, fromto, r) in enumerate(segs):
            name = f"{side}_{seg}"
            s += f'{ind}<body name="{name}" pos="{pos}" euler="{5 * sy} 0 {3 * k}">\n'
            for a in jaxes:
                axis = {"x": "1 0 0", "y": "0 1 0", "z": "0 0 1"}[a]
                jpos = "0 0 0.01" if (a == "y" and seg in ("elbow", "knee")) else "0 0 0"
                s += f'{ind}  <joint name="{name}_{a}" axis="{axis}" pos="{jpos}" range="-120 120"/>\n'
            if seg in ("wrist",):
                s += f'{ind}  <inertial pos="0 0 -0.05" quat="0.9 0.1 0.2 0.1" mass="0.4" diaginertia="0.0006 0.0005 0.0003"/>\n'
            s += f'{ind}  <geom class="limb" fromto="{fromto}" size="{r}"/>\n'
            close = f"{ind}</body>\n" + close
            ind += "  "
        return s + close

    body = '    <body name="pelvis" pos="0 0 1.1" quat="0.99 0 0.05 0.1">\n      <freejoint name="root"/>\n'
    body += '      <geom type="box" size="0.1 0.15 0.08" density="900"/>\n'
    body += '      <body name="torso" pos="0 0 0.12">\n        <joint name="spine_y" axis="0 1 0" range="-30 40"/>\n        <joint name="spine_x" axis="1 0 0" pos="0 0 0.02" range="-30 30"/>\n'
    body += '        <geom type="capsule" fromto="0 -0.1 0.2 0 0.1 0.2" size="0.09"/>\n        <geom type="ellipsoid" pos="0 0 0.08" size="0.12 0.15 0.12"/>\n'
    body += '        <body name="head" pos="0 0 0.4">\n          <joint name="neck" type="ball"/>\n          <geom type="sphere" pos="0 0 0.1" size="0.1"/>\n          <site name="eyes" pos="0.09 0 0.12"/>\n        </body>\n'
    for side, sy in (("left", 1), ("right", -1)):
        body += "\n".join("  " + l if l else l for l in limb(side + "_arm", sy, True).split("\n"))
    body += "      </body>\n"
    for side, sy in (("left", 1), ("right", -1)):
        body += limb(side + "_leg", sy, False)
    body += "    </body>\n"
    return f"""<mujoco model="humanoid">
  <compiler angle="degree" inertiafromgeom="auto"/>
  <option timestep="0.002" gravity="0 0 -9.81"/>
  <default>
    <joint type="hinge" damping="0.5"/>
    <default class="limb">
      <geom type="capsule" density="1050" rgba="0.7 0.6 0.5 1"/>
    </default>
  </default>
  <worldbody>
    <geom name="floor" type="plane" size="10 10 0.1"/>
    <light pos="0 0 4"/>
{body}  </worldbody>
  <actuator>
    <motor joint="left_leg_knee_y" gear="100"/>
  </actuator>
</mujoco>
"""


def main():
    os.makedirs(OUT, exist_ok=True)
    files = {
        "arm7.urdf": arm7(),
        "quadruped.urdf": quadruped(),
        "double_pendulum.urdf": double_pendulum_urdf(),
        "double_pendulum.xml": double_pendulum_mjcf(),
        "top.xml": top_mjcf(),
        "four_bar.xml": fourbar_mjcf(),
        "humanoid.xml": humanoid_mjcf(),
    }
    for name, text in files.items():
        with open(os.path.join(OUT, name), "w") as f:
            f.write(text)
    print("wrote", ", ".join(sorted(files)))


if __name__ == "__main__":
    main()
