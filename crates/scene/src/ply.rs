//! Meshes from PLY files (the "Polygon File Format" of Greg Turk, 1994),
//! ASCII and binary, read and written with the `ply-rs-bw` crate.
//!
//! The sheet's framework reads its test meshes from PLY files (section
//! 3.3). A mesh file has a `vertex` element with `x`, `y`, `z` and
//! optionally `red`, `green`, `blue` (and `alpha`), and a `face` element
//! with a list property `vertex_indices` (or `vertex_index`):
//!
//! ```text
//! ply
//! format ascii 1.0
//! element vertex 3
//! property float x
//! property float y
//! property float z
//! property uchar red
//! property uchar green
//! property uchar blue
//! element face 1
//! property list uchar uint vertex_indices
//! end_header
//! 0 0 0 255 0 0
//! 1 0 0 0 255 0
//! 0 1 0 0 0 255
//! 3 0 1 2
//! ```
//!
//! Every malformed file gives a [`PlyError`] naming the file and where the
//! problem is: a line of the header or of an ASCII payload, or an element
//! and its 0-based index in a binary payload. The reader never panics and
//! does work proportional to the input's size: before the payload is read,
//! the element counts the header declares are checked against the bytes
//! that follow (at least one byte per entry), so a header claiming 10⁹
//! vertices fails at once.

use std::fmt;
use std::io::ErrorKind as IoKind;
use std::path::Path;

use canvas::Rgba;
use glam::Vec3;
use ply_rs_bw::parser::{ParseError, Parser, Reader};
use ply_rs_bw::ply::{
    Addable, DefaultElement, ElementDef, Encoding, Header, Ply, Property, PropertyDef,
    PropertyType, ScalarType,
};
use ply_rs_bw::writer::Writer;

use crate::Mesh;

/// The element holding vertex positions and colours.
pub const VERTEX: &str = "vertex";
/// The element holding faces.
pub const FACE: &str = "face";
/// The names the face's index list may have (the first is written).
pub const FACE_INDICES: [&str; 2] = ["vertex_indices", "vertex_index"];
/// The fewest corners a face may have.
pub const MIN_CORNERS: usize = 3;

/// Where in a file an error was found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Location {
    /// The file as a whole (it could not be read, or ends with extra data).
    File,
    /// The header, without a line number (e.g. the `format` line is
    /// missing, or a declaration contradicts the size of the file).
    Header,
    /// A line (1-based) of the header or of an ASCII payload.
    Line(usize),
    /// An entry of an element (0-based index), in any encoding.
    Element {
        /// The element's name, e.g. `vertex`.
        element: String,
        /// The entry's index within the element.
        index: usize,
    },
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::File => f.write_str("file"),
            Self::Header => f.write_str("header"),
            Self::Line(line) => write!(f, "line {line}"),
            Self::Element { element, index } => write!(f, "{element} {index}"),
        }
    }
}

/// What is wrong with a PLY file.
#[derive(Debug, thiserror::Error)]
pub enum PlyErrorKind {
    /// The file could not be read.
    #[error("cannot read the file: {0}")]
    Io(std::io::Error),
    /// The file ends before every declared element was read.
    #[error("the file ends too early: {0}")]
    Truncated(String),
    /// The header or an ASCII line does not parse: an unknown format, a bad
    /// number, a missing value. The message is the PLY parser's.
    #[error("{0}")]
    Syntax(String),
    /// The `format` line names no known encoding (or no valid version).
    #[error(
        "unknown format '{0}': expected ascii, binary_little_endian or binary_big_endian, version 1.0"
    )]
    UnknownFormat(String),
    /// The elements declare more entries than there are bytes after the
    /// header (checked before reading, see [`parse`]).
    #[error(
        "element '{element}' declares {declared} entries, more than the {available} bytes after the header can hold"
    )]
    CountTooLarge {
        /// The element.
        element: String,
        /// The declared count.
        declared: usize,
        /// The bytes after the header.
        available: usize,
    },
    /// Data follows the last declared element (the header declares too few
    /// entries).
    #[error("{0} bytes follow the last declared element")]
    TrailingData(usize),
    /// The file has no element of this name.
    #[error("there is no '{0}' element")]
    MissingElement(&'static str),
    /// An element lacks a property the mesh needs.
    #[error("element '{element}' has no property '{property}'")]
    MissingProperty {
        /// The element.
        element: &'static str,
        /// The property.
        property: String,
    },
    /// A property has a type the mesh cannot use.
    #[error("property '{property}' is {found:?}, expected {expected}")]
    WrongType {
        /// The property.
        property: String,
        /// What the header declares.
        found: PropertyType,
        /// What would be accepted.
        expected: &'static str,
    },
    /// A vertex coordinate is NaN or infinite.
    #[error("coordinate '{property}' is not finite ({value})")]
    NotFinite {
        /// The coordinate's property name.
        property: &'static str,
        /// Its value.
        value: f64,
    },
    /// A face refers to a vertex that does not exist.
    #[error("corner {corner} refers to vertex {index}, but there are {vertices} vertices")]
    IndexOutOfRange {
        /// The corner's position in the face (0-based).
        corner: usize,
        /// The index found.
        index: i64,
        /// The number of vertices.
        vertices: usize,
    },
    /// A face has fewer than [`MIN_CORNERS`] corners.
    #[error("a face needs at least {MIN_CORNERS} corners, this one has {0}")]
    TooFewCorners(usize),
}

/// An error reading a PLY file: the file, where in it, and what is wrong.
#[derive(Debug, thiserror::Error)]
#[error("{file}: {location}: {kind}")]
pub struct PlyError {
    /// The file's name or path as given to [`load`] or [`parse`].
    pub file: String,
    /// Where the problem is.
    pub location: Location,
    /// What the problem is.
    pub kind: PlyErrorKind,
}

/// How a PLY file's payload is encoded when writing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Numbers as text, one element entry per line.
    Ascii,
    /// Numbers as little-endian binary (the most common binary PLY).
    BinaryLittleEndian,
}

/// Reads a mesh from a PLY file (see [`parse`]).
///
/// # Errors
/// [`PlyErrorKind::Io`] if the file cannot be read, else as [`parse`].
pub fn load(path: impl AsRef<Path>) -> Result<Mesh, PlyError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    match std::fs::read(path) {
        Ok(bytes) => parse(&bytes, &file),
        Err(e) => Err(PlyError {
            file,
            location: Location::File,
            kind: PlyErrorKind::Io(e),
        }),
    }
}

/// Reads a mesh from the bytes of a PLY file; `name` is the file name used
/// in errors.
///
/// Accepts the ASCII, binary little-endian and binary big-endian encodings.
/// Positions may have any numeric type and are converted to `f32`; colours
/// are `uchar` (divided by 255), `ushort` (divided by 65535), `float` or
/// `double` (taken as they are); vertices without colours are white. Other
/// elements and properties are ignored. A file without a `face` element
/// gives a mesh without faces.
///
/// # Errors
/// A [`PlyError`] with its location for a malformed header or payload, a
/// truncated file, counts that do not match the data, a missing or
/// mistyped property, a non-finite coordinate, a face with fewer than
/// [`MIN_CORNERS`] corners or an index out of range.
pub fn parse(bytes: &[u8], name: &str) -> Result<Mesh, PlyError> {
    let error = |location, kind| PlyError {
        file: name.to_owned(),
        location,
        kind,
    };
    let parser = Parser::<DefaultElement>::new();
    let mut reader = Reader::new(bytes);
    let header = parser.read_header(&mut reader).map_err(|e| {
        let location = line_or(&e, Location::Header);
        let kind = match unknown_format(bytes, &location) {
            Some(format) => PlyErrorKind::UnknownFormat(format),
            None => kind_of(e),
        };
        error(location, kind)
    })?;
    check_counts(&header, reader.get_ref().len()).map_err(|kind| error(Location::Header, kind))?;
    // What the mesh needs from the header is checked before the payload is
    // read.
    let vertex_def = header
        .elements
        .get(VERTEX)
        .ok_or_else(|| error(Location::Header, PlyErrorKind::MissingElement(VERTEX)))?;
    let layout = VertexLayout::of(vertex_def).map_err(|kind| error(Location::Header, kind))?;
    let face_key = match header.elements.get(FACE) {
        Some(def) => Some(face_key(def).map_err(|kind| error(Location::Header, kind))?),
        None => None,
    };

    let mut vertices = Vec::new();
    let mut faces = Vec::new();
    for element in header.elements.values() {
        // The parser counts binary entries as "lines" too: the entry's index
        // is its line minus the line the element started on.
        let first_line = reader.line().max(1);
        let entries = parser
            .read_payload_for_element(&mut reader, element, &header)
            .map_err(|e| {
                let location = match (header.encoding, e.line()) {
                    (Encoding::Ascii, Some(line)) => Location::Line(line),
                    (_, Some(line)) => Location::Element {
                        element: element.name.clone(),
                        index: line.saturating_sub(first_line),
                    },
                    (_, None) => Location::Header,
                };
                error(location, kind_of(e))
            })?;
        match element.name.as_str() {
            VERTEX => vertices = entries,
            FACE => faces = entries,
            _ => {}
        }
    }
    let rest = reader.get_ref();
    let trailing = match header.encoding {
        Encoding::Ascii => rest.iter().any(|b| !b.is_ascii_whitespace()),
        _ => !rest.is_empty(),
    };
    if trailing {
        let location = match header.encoding {
            Encoding::Ascii => Location::Line(reader.line().max(1)),
            _ => Location::File,
        };
        return Err(error(location, PlyErrorKind::TrailingData(rest.len())));
    }

    let mut mesh = Mesh::default();
    for (index, vertex) in vertices.iter().enumerate() {
        let at = || Location::Element {
            element: VERTEX.to_owned(),
            index,
        };
        let (position, colour) = layout.read(vertex).map_err(|kind| error(at(), kind))?;
        mesh.positions.push(position);
        mesh.colours.push(colour);
    }
    if let Some(key) = face_key {
        for (index, face) in faces.iter().enumerate() {
            let at = || Location::Element {
                element: FACE.to_owned(),
                index,
            };
            let corners = face_indices(face.get(key), mesh.positions.len())
                .map_err(|kind| error(at(), kind))?;
            mesh.faces.push(corners);
        }
    }
    Ok(mesh)
}

/// The format named on a `format` line the parser rejected, if the error
/// is on such a line.
fn unknown_format(bytes: &[u8], location: &Location) -> Option<String> {
    let Location::Line(line) = *location else {
        return None;
    };
    let text = bytes.split(|&b| b == b'\n').nth(line.checked_sub(1)?)?;
    let text = String::from_utf8_lossy(text);
    let mut words = text.split_whitespace();
    (words.next()? == "format").then(|| words.next().unwrap_or("").to_owned())
}

/// The location a parser error names: its line, or `fallback`.
fn line_or(e: &ParseError, fallback: Location) -> Location {
    e.line().map_or(fallback, Location::Line)
}

fn kind_of(e: ParseError) -> PlyErrorKind {
    let message = tidy(&e.to_string());
    match e.kind() {
        IoKind::UnexpectedEof => PlyErrorKind::Truncated(message),
        _ => PlyErrorKind::Syntax(message),
    }
}

/// The parser's message on one line: without its own "Line N: " prefix (the
/// location is reported separately), and for its nested form
/// `context \n\tString: 'text'\n\tError: inner ...` only the text and the
/// innermost error.
fn tidy(message: &str) -> String {
    let message = match message.split_once(": ") {
        Some((head, rest)) if head.starts_with("Line ") => rest,
        _ => message,
    };
    let innermost = message.rsplit("Error: ").next().unwrap_or(message).trim();
    let text = message
        .split_once("String: ")
        .map(|(_, rest)| rest.lines().next().unwrap_or("").trim_matches(['\'', ' ']));
    let first = message.lines().next().unwrap_or("").trim();
    match text {
        Some(text) => format!("{first} `{text}`: {innermost}"),
        None => message.split_whitespace().collect::<Vec<_>>().join(" "),
    }
}

/// Checks that the declared entries can fit into the `available` bytes after
/// the header, so that the reader's work is bounded by the file's size.
///
/// Every entry is counted as at least one byte: true for ASCII (its line
/// break) and for binary entries with a property. A binary element without
/// properties takes no bytes at all, so without this bound a header could
/// declare 10¹⁸ of them and reading would never end; here such an element
/// may have at most as many entries as there are bytes left. (A stricter
/// bound, the full size of each binary entry, would report a truncated file
/// here, in the header, instead of at the entry where it is cut.)
fn check_counts(header: &Header, available: usize) -> Result<(), PlyErrorKind> {
    let mut needed = 0usize;
    for element in header.elements.values() {
        needed = needed.saturating_add(element.count);
        if needed > available {
            return Err(PlyErrorKind::CountTooLarge {
                element: element.name.clone(),
                declared: element.count,
                available,
            });
        }
    }
    Ok(())
}

/// A scalar property's value as `f64`, or `None` for a list.
fn scalar(p: &Property) -> Option<f64> {
    Some(match *p {
        Property::Char(v) => v.into(),
        Property::UChar(v) => v.into(),
        Property::Short(v) => v.into(),
        Property::UShort(v) => v.into(),
        Property::Int(v) => v.into(),
        Property::UInt(v) => v.into(),
        Property::Float(v) => v.into(),
        Property::Double(v) => v,
        _ => return None,
    })
}

/// Which vertex properties a file has, checked once from the header.
struct VertexLayout {
    /// Scale from the stored colour value to `[0, 1]`; `None` without colours.
    colour_scale: Option<f64>,
    alpha: bool,
}

/// The coordinate properties.
const XYZ: [&str; 3] = ["x", "y", "z"];
/// The colour properties.
const RGB: [&str; 3] = ["red", "green", "blue"];

impl VertexLayout {
    fn of(def: &ElementDef) -> Result<Self, PlyErrorKind> {
        let missing = |property: &str| PlyErrorKind::MissingProperty {
            element: VERTEX,
            property: property.to_owned(),
        };
        for name in XYZ {
            match def.properties.get(name) {
                None => return Err(missing(name)),
                Some(p) if matches!(p.data_type, PropertyType::List(..)) => {
                    return Err(PlyErrorKind::WrongType {
                        property: name.to_owned(),
                        found: p.data_type.clone(),
                        expected: "a number",
                    });
                }
                Some(_) => {}
            }
        }
        let colour_names = RGB.iter().chain(["alpha"].iter());
        let present: Vec<_> = colour_names
            .clone()
            .filter_map(|n| def.properties.get(*n))
            .collect();
        if present.is_empty() {
            return Ok(Self {
                colour_scale: None,
                alpha: false,
            });
        }
        if let Some(name) = RGB.iter().find(|n| !def.properties.contains_key(**n)) {
            return Err(missing(name));
        }
        // All colour channels must share one type, so that one scale fits.
        let first = &present[0].data_type;
        let scale = match first {
            PropertyType::Scalar(ScalarType::UChar) => 255.0,
            PropertyType::Scalar(ScalarType::UShort) => 65535.0,
            PropertyType::Scalar(ScalarType::Float | ScalarType::Double) => 1.0,
            other => {
                return Err(PlyErrorKind::WrongType {
                    property: present[0].name.clone(),
                    found: other.clone(),
                    expected: "uchar, ushort, float or double",
                });
            }
        };
        if let Some(p) = present.iter().find(|p| &p.data_type != first) {
            return Err(PlyErrorKind::WrongType {
                property: p.name.clone(),
                found: p.data_type.clone(),
                expected: "the type of the other colour channels",
            });
        }
        Ok(Self {
            colour_scale: Some(scale),
            alpha: def.properties.contains_key("alpha"),
        })
    }

    fn read(&self, v: &DefaultElement) -> Result<(Vec3, Rgba), PlyErrorKind> {
        let mut xyz = [0.0f32; 3];
        for (slot, name) in xyz.iter_mut().zip(XYZ) {
            // Present and scalar: checked against the header by `of`.
            let value = v.get(name).and_then(scalar).unwrap_or(f64::NAN);
            let narrowed = value as f32;
            if !narrowed.is_finite() {
                return Err(PlyErrorKind::NotFinite {
                    property: name,
                    value,
                });
            }
            *slot = narrowed;
        }
        let colour = match self.colour_scale {
            None => Rgba::WHITE,
            Some(scale) => {
                let channel = |n: &str| (v.get(n).and_then(scalar).unwrap_or(scale) / scale) as f32;
                let alpha = if self.alpha { channel("alpha") } else { 1.0 };
                Rgba::new(channel("red"), channel("green"), channel("blue"), alpha)
            }
        };
        Ok((Vec3::from_array(xyz), colour))
    }
}

/// The face element's index-list property name.
fn face_key(def: &ElementDef) -> Result<&'static str, PlyErrorKind> {
    let Some(key) = FACE_INDICES
        .into_iter()
        .find(|k| def.properties.contains_key(*k))
    else {
        return Err(PlyErrorKind::MissingProperty {
            element: FACE,
            property: FACE_INDICES[0].to_owned(),
        });
    };
    match &def.properties[key].data_type {
        PropertyType::List(_, t) if !matches!(t, ScalarType::Float | ScalarType::Double) => Ok(key),
        other => Err(PlyErrorKind::WrongType {
            property: key.to_owned(),
            found: other.clone(),
            expected: "a list of integers",
        }),
    }
}

/// The corners of one face, checked against the vertex count.
fn face_indices(list: Option<&Property>, vertices: usize) -> Result<Vec<u32>, PlyErrorKind> {
    let raw: Vec<i64> = match list {
        Some(Property::ListChar(v)) => v.iter().map(|&i| i.into()).collect(),
        Some(Property::ListUChar(v)) => v.iter().map(|&i| i.into()).collect(),
        Some(Property::ListShort(v)) => v.iter().map(|&i| i.into()).collect(),
        Some(Property::ListUShort(v)) => v.iter().map(|&i| i.into()).collect(),
        Some(Property::ListInt(v)) => v.iter().map(|&i| i.into()).collect(),
        Some(Property::ListUInt(v)) => v.iter().map(|&i| i.into()).collect(),
        // The header was checked by `face_key`; an entry without the list
        // (which the parser never produces) reads as an empty face.
        _ => Vec::new(),
    };
    if raw.len() < MIN_CORNERS {
        return Err(PlyErrorKind::TooFewCorners(raw.len()));
    }
    raw.iter()
        .enumerate()
        .map(|(corner, &index)| match u32::try_from(index) {
            Ok(i) if (i as usize) < vertices => Ok(i),
            _ => Err(PlyErrorKind::IndexOutOfRange {
                corner,
                index,
                vertices,
            }),
        })
        .collect()
}

/// Writes a mesh as PLY bytes.
///
/// Positions are written as `float`, colours as `uchar` `red`, `green`,
/// `blue` (rounded to 8 bits like a canvas; `alpha` too when some colour is
/// not opaque), faces as `vertex_indices` lists with a `uchar` count (a
/// `uint` count when a face has more than 255 corners). Missing colours
/// (fewer colours than positions) are written white.
#[must_use]
pub fn to_bytes(mesh: &Mesh, format: Format) -> Vec<u8> {
    let mut ply = Ply::<DefaultElement>::new();
    ply.header.encoding = match format {
        Format::Ascii => Encoding::Ascii,
        Format::BinaryLittleEndian => Encoding::BinaryLittleEndian,
    };
    let colour = |i: usize| mesh.colours.get(i).copied().unwrap_or(Rgba::WHITE);
    let alpha = (0..mesh.positions.len()).any(|i| colour(i).to_rgba8()[3] != u8::MAX);

    let mut vertex = ElementDef::new(VERTEX.to_owned());
    for name in XYZ {
        vertex.properties.add(PropertyDef::new(
            name.to_owned(),
            PropertyType::Scalar(ScalarType::Float),
        ));
    }
    let channels: &[&str] = if alpha {
        &["red", "green", "blue", "alpha"]
    } else {
        &RGB
    };
    for &name in channels {
        vertex.properties.add(PropertyDef::new(
            name.to_owned(),
            PropertyType::Scalar(ScalarType::UChar),
        ));
    }
    let long_faces = mesh.faces.iter().any(|f| f.len() > usize::from(u8::MAX));
    let count_type = if long_faces {
        ScalarType::UInt
    } else {
        ScalarType::UChar
    };
    let mut face = ElementDef::new(FACE.to_owned());
    face.properties.add(PropertyDef::new(
        FACE_INDICES[0].to_owned(),
        PropertyType::List(count_type, ScalarType::UInt),
    ));
    ply.header.elements.add(vertex);
    ply.header.elements.add(face);

    let vertices = mesh
        .positions
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let mut e = DefaultElement::new();
            for (name, value) in XYZ.iter().zip(p.to_array()) {
                e.insert((*name).to_owned(), Property::Float(value));
            }
            for (name, value) in channels.iter().zip(colour(i).to_rgba8()) {
                e.insert((*name).to_owned(), Property::UChar(value));
            }
            e
        })
        .collect();
    let faces = mesh
        .faces
        .iter()
        .map(|f| {
            let mut e = DefaultElement::new();
            e.insert(FACE_INDICES[0].to_owned(), Property::ListUInt(f.clone()));
            e
        })
        .collect();
    ply.payload.insert(VERTEX.to_owned(), vertices);
    ply.payload.insert(FACE.to_owned(), faces);

    let mut bytes = Vec::new();
    // Writing to a Vec cannot fail, and the Ply built above is consistent
    // (every entry has exactly the declared properties).
    if let Err(e) = Writer::new().write_ply(&mut bytes, &mut ply) {
        unreachable!("writing a consistent PLY to memory failed: {e}");
    }
    bytes
}

/// Writes a mesh to a PLY file (see [`to_bytes`]).
///
/// # Errors
/// If the file cannot be written.
pub fn save(mesh: &Mesh, path: impl AsRef<Path>, format: Format) -> std::io::Result<()> {
    std::fs::write(path, to_bytes(mesh, format))
}
