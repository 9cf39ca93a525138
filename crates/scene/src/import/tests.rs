//! Bad input to the loaders: each refusal names the element and its line (issue 35).

use std::path::Path;

use super::mjcf::load_mjcf;
use super::urdf::load_urdf;
use crate::SceneError;

fn urdf_err(text: &str) -> (usize, String) {
    match load_urdf(text, "t.urdf") {
        Err(SceneError::Parse { line, message, .. }) => (line, message),
        other => panic!("expected a located error, got {other:?}"),
    }
}

const LINK: &str =
    r#"<link name="L"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1"/></inertial></link>"#;

fn link(name: &str) -> String {
    LINK.replace("\"L\"", &format!("\"{name}\""))
}

fn joint(name: &str, kind: &str, parent: &str, child: &str) -> String {
    format!(r#"<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/></joint>"#)
}

#[test]
fn malformed_xml_is_located() {
    let (line, m) = urdf_err("<robot name=\"r\">\n<link name=\"a\">\n</robot>");
    assert_eq!(line, 3);
    assert!(m.contains("malformed XML"), "{m}");
}

#[test]
fn an_unknown_joint_type_names_the_joint_and_its_line() {
    let text = format!(
        "<robot name=\"r\">\n{}\n{}\n{}\n</robot>",
        link("a"),
        link("b"),
        joint("j", "screw", "a", "b")
    );
    let (line, m) = urdf_err(&text);
    assert_eq!(line, 4);
    assert!(m.contains("<joint>") && m.contains("`screw`") && m.contains("valid: revolute"), "{m}");
}

#[test]
fn a_cycle_and_two_roots_are_refused() {
    let cyc = format!(
        "<robot name=\"r\">\n{}\n{}\n{}\n{}\n{}\n{}\n</robot>",
        link("g"),
        link("a"),
        link("b"),
        joint("j0", "revolute", "g", "a"),
        joint("j1", "revolute", "a", "b"),
        joint("j2", "revolute", "b", "a"),
    );
    let (line, m) = urdf_err(&cyc);
    assert_eq!(line, 7);
    assert!(m.contains("already has parent joint"), "{m}");
    let ring = format!(
        "<robot name=\"r\">\n{}\n{}\n{}\n{}\n</robot>",
        link("a"),
        link("b"),
        joint("j1", "revolute", "a", "b"),
        joint("j2", "revolute", "b", "a"),
    );
    let (_, m) = urdf_err(&ring);
    assert!(m.contains("cycle"), "{m}");
    let two = format!("<robot name=\"r\">\n{}\n{}\n</robot>", link("a"), link("b"));
    let (line, m) = urdf_err(&two);
    assert_eq!(line, 3);
    assert!(m.contains("two root links") && m.contains("(line 2)"), "{m}");
}

#[test]
fn zero_indefinite_and_nan_inertias_are_refused_at_the_inertial() {
    for (inertia, want) in [
        (r#"<mass value="0"/><inertia ixx="1" iyy="1" izz="1"/>"#, "mass 0"),
        (r#"<mass value="1"/><inertia ixx="1" iyy="-1" izz="1"/>"#, "not positive definite"),
        (r#"<mass value="1"/><inertia ixx="1" iyy="1" izz="3"/>"#, "triangle inequality"),
        (r#"<mass value="NaN"/><inertia ixx="1" iyy="1" izz="1"/>"#, "not finite"),
    ] {
        let text = format!(
            "<robot name=\"r\">\n{}\n<link name=\"b\">\n<inertial>{inertia}</inertial></link>\n{}\n</robot>",
            link("a"),
            joint("j", "revolute", "a", "b")
        );
        let (line, m) = urdf_err(&text);
        assert_eq!(line, 4, "{m}");
        assert!(m.contains(want), "{want}: {m}");
    }
}

#[test]
fn a_hundred_thousand_links_are_refused_before_parsing() {
    let mut text = String::from("<robot name=\"big\">\n");
    for k in 0..100_000 {
        text.push_str(&link(&format!("l{k}")));
    }
    text.push_str("</robot>");
    let (line, m) = urdf_err(&text);
    assert_eq!(line, 1);
    assert!(m.contains("more than 10000 links"), "{m}");
}

#[test]
fn meshes_are_never_opened_and_are_listed() {
    // a package:// and an absolute mesh path: nothing is read, both are listed with lines
    let text = format!(
        "<robot name=\"r\">\n{}\n<link name=\"b\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\"/></inertial>\n\
         <visual><geometry><mesh filename=\"package://x/y.stl\"/></geometry></visual>\n\
         <collision><geometry><mesh filename=\"/etc/passwd\"/></geometry></collision></link>\n{}\n</robot>",
        link("a"),
        joint("j", "continuous", "a", "b")
    );
    let m = load_urdf(&text, "t.urdf").unwrap();
    let lines: Vec<usize> = m.warnings.iter().map(|w| w.line).collect();
    assert_eq!(lines, [4, 5]);
    assert!(m.warnings.iter().all(|w| w.message.contains("never opened")));
    assert_eq!(m.bodies.len(), 1);
}

#[test]
fn a_fixed_joint_merges_by_the_parallel_axis_theorem() {
    // two 1 kg bodies with J = I, the second 2 m along x: 2 kg, centre at 1, J_yy = 2 + 2·1²
    let text = format!(
        "<robot name=\"r\">{}{}{}{}<joint name=\"f\" type=\"fixed\"><parent link=\"b\"/><child link=\"c\"/><origin xyz=\"2 0 0\"/></joint></robot>",
        link("a"),
        link("b"),
        link("c"),
        joint("j", "revolute", "a", "b")
    );
    let m = load_urdf(&text, "t.urdf").unwrap();
    assert_eq!(m.bodies.len(), 1);
    assert_eq!(m.bodies[0].com, [1.0, 0.0, 0.0]);
    match &m.bodies[0].mass {
        crate::spec::MassSpec::Value { mass, matrix: Some(j), .. } => {
            assert_eq!(*mass, 2.0);
            assert_eq!(*j, [[2.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0]]);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn mjcf_includes_stay_inside_the_folder_and_missing_files_are_named() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    for (file, want) in [
        ("../Cargo.toml", "leaves the folder"),
        ("/etc/passwd", "leaves the folder"),
        ("nothere.xml", "cannot be opened"),
    ] {
        let text = format!("<mujoco>\n  <include file=\"{file}\"/>\n</mujoco>");
        match load_mjcf(&text, "m.xml", &dir) {
            Err(SceneError::Parse { line, message, .. }) => {
                assert_eq!(line, 2, "{message}");
                assert!(message.contains(want), "{file}: {message}");
            }
            other => panic!("{file}: {other:?}"),
        }
    }
}

#[test]
fn mjcf_unknown_joint_type_and_mesh_mass_are_located() {
    let dir = Path::new(".");
    let bad = "<mujoco>\n<worldbody>\n<body>\n<joint type=\"screw\"/>\n<geom size=\"0.1\"/>\n</body>\n</worldbody>\n</mujoco>";
    match load_mjcf(bad, "m.xml", dir) {
        Err(SceneError::Parse { line: 4, message, .. }) => assert!(message.contains("`screw`"), "{message}"),
        other => panic!("{other:?}"),
    }
    let mesh = "<mujoco>\n<worldbody>\n<body>\n<joint/>\n<geom type=\"mesh\" mesh=\"m\"/>\n</body>\n</worldbody>\n</mujoco>";
    match load_mjcf(mesh, "m.xml", dir) {
        Err(SceneError::Parse { line: 5, message, .. }) => {
            assert!(message.contains("<inertial>"), "{message}")
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn mjcf_sphere_inertia_is_two_fifths_m_r_squared() {
    // density 1000, r = 0.1: m = 4/3 π r³ ρ, J = 2/5 m r² (closed form)
    let text = "<mujoco><compiler angle=\"radian\"/><worldbody><body name=\"b\"><joint axis=\"1 0 0\"/><geom size=\"0.1\"/></body></worldbody></mujoco>";
    let m = load_mjcf(text, "m.xml", Path::new(".")).unwrap();
    let mass = 4.0 / 3.0 * std::f64::consts::PI * 1e-3 * 1000.0;
    match &m.bodies[0].mass {
        crate::spec::MassSpec::Value { mass: got, matrix: Some(j), .. } => {
            assert!((got - mass).abs() <= 1e-15 * mass);
            assert!((j[0][0] - 0.4 * mass * 0.01).abs() <= 1e-15 * mass * 0.01);
        }
        other => panic!("{other:?}"),
    }
    assert!(m.warnings.is_empty(), "{:?}", m.warnings);
}
