//! The indexed triangle mesh every tessellation produces: one list of
//! vertices (position, unit normal, surface parameters) and one list of
//! triangles as index triples, counter-clockwise in the parameter plane.
//! Written as Wavefront OBJ or ASCII PLY for any viewer.

use std::io::{self, Write};

use glam::{DVec2, DVec3};

use crate::bezier::SurfaceSample;
use crate::error::TessError;

/// An indexed triangle mesh with per-vertex normals and parameters.
#[transcript::evidence]
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Unit normals, one per vertex.
    pub normals: Vec<DVec3>,
    /// Surface parameters `(u, v)`, one per vertex (global parameters for a
    /// patch grid: patch `(row, col)` covers `[col, col + 1] × [row, row + 1]`).
    pub uvs: Vec<DVec2>,
    /// Triangles: three vertex indices each.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// An empty mesh.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends a vertex and returns its index.
    pub fn push_vertex(&mut self, point: SurfaceSample) -> u32 {
        let index = u32::try_from(self.positions.len()).expect("fewer than 2³² vertices");
        self.positions.push(point.position);
        self.normals.push(point.normal);
        self.uvs.push(point.uv);
        index
    }

    /// Vertex `index` as a surface point.
    ///
    /// # Panics
    /// If `index` is out of range.
    #[must_use]
    pub fn vertex(&self, index: u32) -> SurfaceSample {
        let i = index as usize;
        SurfaceSample {
            uv: self.uvs[i],
            position: self.positions[i],
            normal: self.normals[i],
        }
    }

    /// Number of vertices.
    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Checks that the attribute lists have one entry per vertex and that
    /// every index names a vertex.
    ///
    /// # Errors
    /// [`TessError::Mesh`] saying which rule is broken.
    pub fn validate(&self) -> Result<(), TessError> {
        let n = self.positions.len();
        if self.normals.len() != n || self.uvs.len() != n {
            return Err(TessError::Mesh("attribute lists differ in length"));
        }
        if self.triangles.iter().flatten().any(|&i| i as usize >= n) {
            return Err(TessError::Mesh("a triangle names a missing vertex"));
        }
        Ok(())
    }

    /// Writes Wavefront OBJ: `v`, `vn` and `vt` lines per vertex, `f i/i/i`
    /// per triangle (OBJ counts from 1). Indices are written as they are,
    /// valid or not (see [`Self::validate`]).
    ///
    /// # Errors
    /// Whatever `out` returns.
    pub fn write_obj(&self, mut out: impl Write) -> io::Result<()> {
        writeln!(
            out,
            "# {} vertices, {} triangles",
            self.vertex_count(),
            self.triangle_count()
        )?;
        for p in &self.positions {
            writeln!(out, "v {} {} {}", p.x, p.y, p.z)?;
        }
        for n in &self.normals {
            writeln!(out, "vn {} {} {}", n.x, n.y, n.z)?;
        }
        for t in &self.uvs {
            writeln!(out, "vt {} {}", t.x, t.y)?;
        }
        for [a, b, c] in &self.triangles {
            // In u64: index u32::MAX + 1 must not overflow.
            let [a, b, c] = [a, b, c].map(|&i| u64::from(i) + 1);
            writeln!(out, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}")?;
        }
        Ok(())
    }

    /// Writes ASCII PLY 1.0: vertices with `x y z nx ny nz u v`, faces as
    /// `3 a b c` (PLY counts from 0).
    ///
    /// # Errors
    /// Whatever `out` returns.
    pub fn write_ply(&self, mut out: impl Write) -> io::Result<()> {
        writeln!(out, "ply\nformat ascii 1.0")?;
        writeln!(out, "element vertex {}", self.vertex_count())?;
        for name in ["x", "y", "z", "nx", "ny", "nz", "u", "v"] {
            writeln!(out, "property double {name}")?;
        }
        writeln!(out, "element face {}", self.triangle_count())?;
        writeln!(out, "property list uchar uint vertex_indices\nend_header")?;
        for ((p, n), t) in self.positions.iter().zip(&self.normals).zip(&self.uvs) {
            writeln!(
                out,
                "{} {} {} {} {} {} {} {}",
                p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y
            )?;
        }
        for [a, b, c] in &self.triangles {
            writeln!(out, "3 {a} {b} {c}")?;
        }
        Ok(())
    }
}
