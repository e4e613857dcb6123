//! The PLY reader and writer: known meshes, round trips, every kind of
//! malformed file with its location, and no panic on any input.

use canvas::Rgba;
use glam::Vec3;
use proptest::prelude::*;
use scene::Mesh;
use scene::ply::{self, Format, Location, PlyErrorKind};

/// The module documentation's example: one triangle with red, green and
/// blue corners. Line numbers: header 1–12, vertices 13–15, face 16.
const TRIANGLE: &str = "ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
property uchar red
property uchar green
property uchar blue
element face 1
property list uchar uint vertex_indices
end_header
0 0 0 255 0 0
1 0 0 0 255 0
0 1 0 0 0 255
3 0 1 2
";

fn triangle() -> Mesh {
    Mesh {
        positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y],
        colours: vec![Rgba::RED, Rgba::GREEN, Rgba::BLUE],
        faces: vec![vec![0, 1, 2]],
    }
}

/// `TRIANGLE` with one line replaced (1-based).
fn with_line(line: usize, replacement: &str) -> String {
    TRIANGLE
        .lines()
        .enumerate()
        .map(|(i, l)| if i + 1 == line { replacement } else { l })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

/// The binary little-endian header of a mesh with `n` vertices (x y z as
/// float, no colours) and `f` faces.
fn binary_header(n: usize, f: usize) -> Vec<u8> {
    format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {n}\nproperty float x\n\
         property float y\nproperty float z\nelement face {f}\n\
         property list uchar int vertex_indices\nend_header\n"
    )
    .into_bytes()
}

fn push_vertex(bytes: &mut Vec<u8>, p: [f32; 3]) {
    for c in p {
        bytes.extend_from_slice(&c.to_le_bytes());
    }
}

fn push_face(bytes: &mut Vec<u8>, corners: &[i32]) {
    bytes.push(corners.len() as u8);
    for c in corners {
        bytes.extend_from_slice(&c.to_le_bytes());
    }
}

/// A binary triangle without colours, written byte by byte.
fn binary_triangle() -> Vec<u8> {
    let mut bytes = binary_header(3, 1);
    push_vertex(&mut bytes, [0.0, 0.0, 0.0]);
    push_vertex(&mut bytes, [1.0, 0.0, 0.0]);
    push_vertex(&mut bytes, [0.0, 1.0, 0.0]);
    push_face(&mut bytes, &[0, 1, 2]);
    bytes
}

fn error(bytes: &[u8]) -> scene::PlyError {
    match ply::parse(bytes, "bad.ply") {
        Ok(mesh) => panic!("expected an error, got {mesh:?}"),
        Err(e) => e,
    }
}

fn element(name: &str, index: usize) -> Location {
    Location::Element {
        element: name.to_owned(),
        index,
    }
}

#[test]
fn ascii_triangle_reads_positions_colours_and_face() {
    assert_eq!(
        ply::parse(TRIANGLE.as_bytes(), "t.ply").unwrap(),
        triangle()
    );
}

#[test]
fn binary_triangle_without_colours_is_white() {
    let mesh = ply::parse(&binary_triangle(), "t.ply").unwrap();
    assert_eq!(mesh.positions, triangle().positions);
    assert_eq!(mesh.colours, vec![Rgba::WHITE; 3]);
    assert_eq!(mesh.faces, vec![vec![0, 1, 2]]);
}

#[test]
fn polygons_double_coordinates_and_float_colours_are_read() {
    let text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n\
                property double z\nproperty float red\nproperty float green\nproperty float blue\n\
                element face 1\nproperty list uchar int vertex_index\nend_header\n\
                0 0 0 1 0.5 0\n2 0 0 1 0.5 0\n2 2 0 1 0.5 0\n0 2 -1.5 1 0.5 0\n4 0 1 2 3\n";
    let mesh = ply::parse(text.as_bytes(), "quad.ply").unwrap();
    assert_eq!(mesh.positions[3], Vec3::new(0.0, 2.0, -1.5));
    assert_eq!(mesh.colours[0], Rgba::rgb(1.0, 0.5, 0.0));
    assert_eq!(mesh.faces, vec![vec![0, 1, 2, 3]]);
}

#[test]
fn big_endian_binary_is_read_too() {
    let mut bytes = b"ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n\
                      property float y\nproperty float z\nelement face 1\n\
                      property list uchar int vertex_indices\nend_header\n"
        .to_vec();
    for p in [[0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]] {
        for c in p {
            bytes.extend_from_slice(&c.to_be_bytes());
        }
    }
    bytes.push(3);
    for i in [0i32, 1, 2] {
        bytes.extend_from_slice(&i.to_be_bytes());
    }
    let mesh = ply::parse(&bytes, "be.ply").unwrap();
    assert_eq!(mesh.positions, triangle().positions);
    assert_eq!(mesh.faces, triangle().faces);
}

#[test]
fn translucent_colours_are_written_with_alpha() {
    let mut mesh = triangle();
    mesh.colours[1] = Rgba::from_rgba8([10, 20, 30, 40]);
    let bytes = ply::to_bytes(&mesh, Format::Ascii);
    assert!(String::from_utf8_lossy(&bytes).contains("property uchar alpha\n"));
    assert_eq!(ply::parse(&bytes, "a.ply").unwrap(), mesh);
}

#[test]
fn file_without_faces_gives_mesh_without_faces() {
    let text = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
                property float z\nend_header\n1 2 3\n";
    let mesh = ply::parse(text.as_bytes(), "points.ply").unwrap();
    assert_eq!(mesh.positions, vec![Vec3::new(1.0, 2.0, 3.0)]);
    assert!(mesh.faces.is_empty());
}

#[test]
fn written_files_read_back_identically_in_both_formats() {
    for format in [Format::Ascii, Format::BinaryLittleEndian] {
        let bytes = ply::to_bytes(&triangle(), format);
        assert_eq!(
            ply::parse(&bytes, "t.ply").unwrap(),
            triangle(),
            "{format:?}"
        );
    }
    let ascii = ply::to_bytes(&triangle(), Format::Ascii);
    assert!(ascii.starts_with(b"ply\nformat ascii 1.0\n"));
    let binary = ply::to_bytes(&triangle(), Format::BinaryLittleEndian);
    assert!(binary.starts_with(b"ply\nformat binary_little_endian 1.0\n"));
}

#[test]
fn shipped_meshes_load_in_both_encodings() {
    let mut encodings = Vec::new();
    for name in scene::data::MESHES {
        let path = scene::data::path(name);
        let mesh = ply::load(&path).unwrap_or_else(|e| panic!("{e}"));
        assert!(!mesh.faces.is_empty(), "{name}");
        assert_eq!(mesh.colours.len(), mesh.positions.len(), "{name}");
        let bytes = std::fs::read(&path).unwrap();
        encodings.push(bytes.starts_with(b"ply\nformat ascii"));
    }
    assert!(encodings.contains(&true) && encodings.contains(&false));
}

#[test]
fn shipped_star_is_a_pentagon_with_five_tips() {
    let star = ply::load(scene::data::path("star.ply")).unwrap();
    let mut sizes: Vec<usize> = star.faces.iter().map(Vec::len).collect();
    sizes.sort_unstable();
    assert_eq!(sizes, [3, 3, 3, 3, 3, 5]);
}

#[test]
fn shipped_torus_and_plane_are_quads() {
    for (name, faces) in [("torus.ply", 24 * 12), ("plane.ply", 16)] {
        let mesh = ply::load(scene::data::path(name)).unwrap();
        assert_eq!(mesh.faces.len(), faces, "{name}");
        assert!(mesh.faces.iter().all(|f| f.len() == 4), "{name}");
    }
}

// ---- malformed files: each error names the file and the place ----

#[test]
fn truncated_ascii_file_names_the_missing_line() {
    let text: String = TRIANGLE
        .lines()
        .take(15)
        .map(|l| format!("{l}\n"))
        .collect();
    let e = error(text.as_bytes());
    assert_eq!(e.location, Location::Line(16));
    assert!(matches!(e.kind, PlyErrorKind::Truncated(_)), "{e}");
    assert!(e.to_string().starts_with("bad.ply: line 16: "), "{e}");
}

#[test]
fn truncated_binary_file_names_the_element_entry() {
    let bytes = binary_triangle();
    // Header, two whole vertices and half of the third.
    let cut = binary_header(3, 1).len() + 2 * 12 + 6;
    let e = error(&bytes[..cut]);
    assert_eq!(e.location, element("vertex", 2));
    assert!(matches!(e.kind, PlyErrorKind::Truncated(_)), "{e}");
    // Cut inside the face's index list.
    let e = error(&bytes[..bytes.len() - 2]);
    assert_eq!(e.location, element("face", 0));
    assert!(matches!(e.kind, PlyErrorKind::Truncated(_)), "{e}");
}

#[test]
fn header_without_end_is_truncated() {
    let e = error(b"ply\nformat ascii 1.0\nelement vertex 1\n");
    assert!(matches!(e.kind, PlyErrorKind::Truncated(_)), "{e}");
}

#[test]
fn too_many_declared_vertices_read_the_face_as_a_vertex() {
    // Line 16, the face "3 0 1 2", lacks the colour values of a vertex.
    let e = error(with_line(3, "element vertex 4").as_bytes());
    assert_eq!(e.location, Location::Line(16));
    assert!(matches!(e.kind, PlyErrorKind::Syntax(_)), "{e}");
}

#[test]
fn too_few_declared_vertices_leave_trailing_data() {
    let e = error(with_line(3, "element vertex 2").as_bytes());
    assert_eq!(e.location, Location::Line(16));
    assert!(matches!(e.kind, PlyErrorKind::TrailingData(_)), "{e}");
    let mut bytes = binary_triangle();
    bytes.extend_from_slice(&[0, 0, 0, 0]);
    let e = error(&bytes);
    assert_eq!(e.location, Location::File);
    assert!(matches!(e.kind, PlyErrorKind::TrailingData(4)), "{e}");
}

#[test]
fn counts_larger_than_the_file_fail_before_reading() {
    let e = error(with_line(3, "element vertex 1000000000000").as_bytes());
    assert_eq!(e.location, Location::Header);
    assert!(
        matches!(
            e.kind,
            PlyErrorKind::CountTooLarge {
                declared: 1_000_000_000_000,
                ..
            }
        ),
        "{e}"
    );
    // Binary entries without properties take no bytes; a huge count of
    // them must not make the reader loop.
    let text = "ply\nformat binary_little_endian 1.0\nelement nothing 1000000000000\nend_header\n";
    let e = error(text.as_bytes());
    assert!(matches!(e.kind, PlyErrorKind::CountTooLarge { .. }), "{e}");
}

#[test]
fn bad_number_names_its_line() {
    let e = error(with_line(14, "1 zero 0 0 255 0").as_bytes());
    assert_eq!(e.location, Location::Line(14));
    assert!(matches!(e.kind, PlyErrorKind::Syntax(_)), "{e}");
    // A colour beyond the range of uchar.
    let e = error(with_line(13, "0 0 0 256 0 0").as_bytes());
    assert_eq!(e.location, Location::Line(13));
}

#[test]
fn unknown_format_names_the_format_line() {
    let e = error(with_line(2, "format binary_middle_endian 1.0").as_bytes());
    assert_eq!(e.location, Location::Line(2));
    assert!(
        matches!(&e.kind, PlyErrorKind::UnknownFormat(f) if f == "binary_middle_endian"),
        "{e}"
    );
}

#[test]
fn not_a_ply_file_fails_on_line_one() {
    let e = error(b"OFF\n3 1 0\n");
    assert_eq!(e.location, Location::Line(1));
    let e = error(b"");
    assert!(matches!(e.kind, PlyErrorKind::Truncated(_)), "{e}");
}

#[test]
fn face_index_out_of_range_names_face_and_corner() {
    let e = error(with_line(16, "3 0 1 3").as_bytes());
    assert_eq!(e.location, element("face", 0));
    assert!(
        matches!(
            e.kind,
            PlyErrorKind::IndexOutOfRange {
                corner: 2,
                index: 3,
                vertices: 3
            }
        ),
        "{e}"
    );
    let mut bytes = binary_header(3, 2);
    for p in [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]] {
        push_vertex(&mut bytes, p);
    }
    push_face(&mut bytes, &[0, 1, 2]);
    push_face(&mut bytes, &[0, -1, 2]);
    let e = error(&bytes);
    assert_eq!(e.location, element("face", 1));
    assert!(
        matches!(e.kind, PlyErrorKind::IndexOutOfRange { index: -1, .. }),
        "{e}"
    );
}

#[test]
fn face_with_two_corners_is_rejected() {
    let e = error(with_line(16, "2 0 1").as_bytes());
    assert_eq!(e.location, element("face", 0));
    assert!(matches!(e.kind, PlyErrorKind::TooFewCorners(2)), "{e}");
}

#[test]
fn missing_or_mistyped_properties_are_named() {
    let e = error(with_line(6, "property float w").as_bytes());
    assert_eq!(e.location, Location::Header);
    assert!(
        matches!(&e.kind, PlyErrorKind::MissingProperty { property, .. } if property == "z"),
        "{e}"
    );
    let e = error(with_line(8, "property uchar grey").as_bytes());
    assert!(
        matches!(&e.kind, PlyErrorKind::MissingProperty { property, .. } if property == "green"),
        "{e}"
    );
    let e = error(with_line(11, "property list uchar float vertex_indices").as_bytes());
    assert!(matches!(e.kind, PlyErrorKind::WrongType { .. }), "{e}");
    let e = error(with_line(3, "element point 3").as_bytes());
    assert!(
        matches!(e.kind, PlyErrorKind::MissingElement("vertex")),
        "{e}"
    );
}

#[test]
fn non_finite_coordinates_are_rejected() {
    let mut bytes = binary_header(3, 1);
    push_vertex(&mut bytes, [0.0, 0.0, 0.0]);
    push_vertex(&mut bytes, [1.0, f32::NAN, 0.0]);
    push_vertex(&mut bytes, [0.0, 1.0, f32::INFINITY]);
    push_face(&mut bytes, &[0, 1, 2]);
    let e = error(&bytes);
    assert_eq!(e.location, element("vertex", 1));
    assert!(
        matches!(e.kind, PlyErrorKind::NotFinite { property: "y", .. }),
        "{e}"
    );
}

#[test]
fn missing_file_is_an_io_error_naming_the_path() {
    let e = ply::load("/nonexistent/mesh.ply").unwrap_err();
    assert_eq!(e.location, Location::File);
    assert!(matches!(e.kind, PlyErrorKind::Io(_)), "{e}");
    assert!(e.to_string().starts_with("/nonexistent/mesh.ply: "), "{e}");
}

// ---- properties ----

/// Colours on the 8-bit levels a PLY `uchar` can hold, mostly opaque.
fn colour8() -> impl Strategy<Value = Rgba> {
    let alpha = prop_oneof![9 => Just(u8::MAX), 1 => any::<u8>()];
    (any::<u8>(), any::<u8>(), any::<u8>(), alpha)
        .prop_map(|(r, g, b, a)| Rgba::from_rgba8([r, g, b, a]))
}

fn mesh() -> impl Strategy<Value = Mesh> {
    let vertex = (
        (-1e6f32..1e6, -1e6f32..1e6, -1e6f32..1e6).prop_map(|(x, y, z)| Vec3::new(x, y, z)),
        colour8(),
    );
    prop::collection::vec(vertex, 3..20).prop_flat_map(|vertices| {
        let n = vertices.len() as u32;
        let faces = prop::collection::vec(prop::collection::vec(0..n, 3..8), 0..10);
        (Just(vertices), faces).prop_map(|(vertices, faces)| Mesh {
            positions: vertices.iter().map(|v| v.0).collect(),
            colours: vertices.iter().map(|v| v.1).collect(),
            faces,
        })
    })
}

/// Small edits of a valid file: flip, replace, insert or delete a byte.
#[derive(Clone, Debug)]
enum Edit {
    Replace(usize, u8),
    Insert(usize, u8),
    Delete(usize),
    Truncate(usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Edit::Replace(i, b)),
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Edit::Insert(i, b)),
        any::<usize>().prop_map(Edit::Delete),
        any::<usize>().prop_map(Edit::Truncate),
    ]
}

fn apply(bytes: &mut Vec<u8>, edit: &Edit) {
    let n = bytes.len().max(1);
    match *edit {
        Edit::Replace(i, b) => {
            if let Some(x) = bytes.get_mut(i % n) {
                *x = b;
            }
        }
        Edit::Insert(i, b) => bytes.insert(i % (bytes.len() + 1), b),
        Edit::Delete(i) => {
            if !bytes.is_empty() {
                bytes.remove(i % n);
            }
        }
        Edit::Truncate(i) => bytes.truncate(i % n),
    }
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    #[test]
    fn round_trip_preserves_every_mesh(mesh in mesh(), binary in any::<bool>()) {
        let format = if binary { Format::BinaryLittleEndian } else { Format::Ascii };
        let bytes = ply::to_bytes(&mesh, format);
        prop_assert_eq!(ply::parse(&bytes, "m.ply").unwrap(), mesh);
    }

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        let _ = ply::parse(&bytes, "random.ply");
    }

    #[test]
    fn random_bytes_after_a_valid_header_never_panic(
        binary in any::<bool>(),
        body in prop::collection::vec(any::<u8>(), 0..200),
    ) {
        let mut bytes = if binary { binary_header(3, 2) } else {
            TRIANGLE.lines().take(12).map(|l| format!("{l}\n")).collect::<String>().into_bytes()
        };
        bytes.extend(body);
        let _ = ply::parse(&bytes, "random.ply");
    }

    #[test]
    fn edited_valid_files_never_panic(
        mesh in mesh(),
        binary in any::<bool>(),
        edits in prop::collection::vec(edit(), 1..6),
    ) {
        let format = if binary { Format::BinaryLittleEndian } else { Format::Ascii };
        let mut bytes = ply::to_bytes(&mesh, format);
        for e in &edits {
            apply(&mut bytes, e);
        }
        let _ = ply::parse(&bytes, "edited.ply");
    }

    #[test]
    fn binary_file_cut_anywhere_is_an_error(mesh in mesh(), cut in any::<usize>()) {
        let bytes = ply::to_bytes(&mesh, Format::BinaryLittleEndian);
        let keep = cut % bytes.len();
        prop_assert!(ply::parse(&bytes[..keep], "cut.ply").is_err());
    }

    #[test]
    fn ascii_file_cut_after_any_line_is_an_error(mesh in mesh(), cut in any::<usize>()) {
        // Cutting inside a number may leave a shorter valid number, so the
        // ASCII file is cut at line ends only: a whole entry goes missing.
        let bytes = ply::to_bytes(&mesh, Format::Ascii);
        let ends: Vec<usize> = bytes.iter().enumerate().filter(|(_, b)| **b == b'\n').map(|(i, _)| i + 1).collect();
        let keep = ends[cut % (ends.len() - 1)];
        prop_assert!(ply::parse(&bytes[..keep], "cut.ply").is_err());
    }
}
