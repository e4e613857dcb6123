//! The tessellation scene's stage: what to tessellate and how (seed 001's
//! surfaces, methods and edge tests), and your topic 09 cutting it into
//! triangles, drawn by the topic's given renderer.

use canvas::Canvas;

/// The surfaces to tessellate (topic 09's examples).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    /// Seed 001's example surface, of degree 3 × 2 (Primjer 1.1.5; Slika 2.5).
    SeedSurface,
    /// Seed 000's hill.
    Hill,
    /// Several patches joined with tangent continuity (Slika 2.3).
    Patches,
    /// The NURBS torus: 16 rational biquadratic patches.
    Torus,
    /// The torus from its NURBS data, split by your topic 08.
    NurbsTorus,
    /// The vase (single interior knots), split by your topic 08.
    Vase,
}

impl Surface {
    /// Every surface, in the order of the controls.
    pub const ALL: [Self; 6] = [
        Self::SeedSurface,
        Self::Hill,
        Self::Patches,
        Self::Torus,
        Self::NurbsTorus,
        Self::Vase,
    ];

    /// The NURBS surface your topic 08 splits first, for those that are
    /// one (the chain NURBS → Bézier patches → triangles).
    #[must_use]
    pub fn nurbs(self) -> Option<freeform::NurbsSurfaceData> {
        match self {
            Self::NurbsTorus => Some(freeform::NurbsSurfaceData::torus(0.7, 0.25)),
            Self::Vase => Some(freeform::NurbsSurfaceData::vase()),
            Self::SeedSurface | Self::Hill | Self::Patches | Self::Torus => None,
        }
    }

    /// Its name on screen.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::SeedSurface => "The seed's patch",
            Self::Hill => "The hill",
            Self::Patches => "Several patches",
            Self::Torus => "NURBS torus (16 rational patches, given)",
            Self::NurbsTorus => "NURBS torus, split by your topic 08",
            Self::Vase => "NURBS vase (single knots), split by your topic 08",
        }
    }
}

/// The three methods of the topic's tasks 1–3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// The same grid on every patch (task 1).
    Uniform,
    /// A grid per patch from a chord tolerance, stitched without cracks
    /// (task 2).
    PerPatch,
    /// A uniform start refined edge by edge where an edge test asks for it
    /// (task 3).
    FullyAdaptive,
}

impl Method {
    /// Every method, in the order of the controls.
    pub const ALL: [Self; 3] = [Self::Uniform, Self::PerPatch, Self::FullyAdaptive];

    /// Its name on screen.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::Uniform => "Uniform",
            Self::PerPatch => "Per patch",
            Self::FullyAdaptive => "Fully adaptive",
        }
    }

    /// Your code that does it.
    #[must_use]
    pub fn source(self) -> &'static str {
        match self {
            Self::Uniform => "09-tessellation · uniform::tessellate_uniform",
            Self::PerPatch => {
                "09-tessellation · per_patch::tessellate_patch_grid (patch_resolution, curve_segments)"
            }
            Self::FullyAdaptive => {
                "09-tessellation · fully_adaptive::refine with edge_tests, from tessellate_uniform"
            }
        }
    }
}

/// The seven edge tests of seed 001 §2.2.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Test {
    /// (2.1), threshold `t1`.
    OneEdgeNormal,
    /// (2.3), thresholds `t1` and `t2`.
    OneEdgeComplementary,
    /// (2.4), threshold `t3`.
    TwoTriangle,
    /// (2.5), threshold `t3`.
    FirstOrderNeighbour,
    /// (2.6), threshold `t1`.
    VectorDeviationFlat,
    /// Local flatness, threshold `t1`.
    LocalFlat,
    /// (2.7), threshold `t1`.
    UmbrellaFlat,
}

impl Test {
    /// Every test, in the order of the controls.
    pub const ALL: [Self; 7] = [
        Self::OneEdgeNormal,
        Self::OneEdgeComplementary,
        Self::TwoTriangle,
        Self::FirstOrderNeighbour,
        Self::VectorDeviationFlat,
        Self::LocalFlat,
        Self::UmbrellaFlat,
    ];

    /// Its name on screen.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::OneEdgeNormal => "One-edge normal (2.1)",
            Self::OneEdgeComplementary => "One-edge complementary (2.3)",
            Self::TwoTriangle => "Two-triangle (2.4)",
            Self::FirstOrderNeighbour => "First-order neighbour (2.5)",
            Self::VectorDeviationFlat => "Vector deviation flatness (2.6)",
            Self::LocalFlat => "Local flatness",
            Self::UmbrellaFlat => "Umbrella flatness (2.7)",
        }
    }

    /// The thresholds the topic's tests use for it: a start that refines
    /// visibly but not without end.
    #[must_use]
    pub fn default_thresholds(self) -> [f64; 2] {
        match self {
            Self::OneEdgeNormal => [0.2, 0.3],
            Self::OneEdgeComplementary => [0.2, 0.3],
            Self::TwoTriangle | Self::FirstOrderNeighbour | Self::LocalFlat => [0.1, 0.3],
            Self::VectorDeviationFlat => [0.003, 0.3],
            Self::UmbrellaFlat => [0.95, 0.3],
        }
    }
}

/// How the triangles are shown (topic 09's `render::Style`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Look {
    /// The lit surface.
    Shaded,
    /// The visible edges alone.
    Wireframe,
    /// The lit surface with its edges.
    Both,
}

/// What to tessellate and how.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TessSetup {
    /// The surface.
    pub surface: Surface,
    /// The method.
    pub method: Method,
    /// Cells per side of each patch (uniform), or of the start of the
    /// fully adaptive refinement, `1 ..= 64`.
    pub level: u32,
    /// The chord tolerance of the per-patch method.
    pub tolerance: f64,
    /// The fully adaptive method's edge test.
    pub test: Test,
    /// Its thresholds (the second only for the complementary test).
    pub thresholds: [f64; 2],
    /// The most times an edge is halved.
    pub depth: u32,
    /// How the triangles show.
    pub look: Look,
    /// The camera's orbit around the surface (its z, the world's up),
    /// degrees.
    pub yaw: f64,
    /// The camera's height above the surface's plane, degrees (the
    /// opposite of its tilt: see `scene::turn`).
    pub pitch: f64,
    /// The picture's side in pixels.
    pub size: u32,
}

/// The highest level offered.
pub const MAX_LEVEL: u32 = 64;
/// The deepest refinement offered (topic 09's `MAX_DEPTH`).
pub const MAX_DEPTH: u32 = 12;

impl Default for TessSetup {
    /// The NURBS torus, uniform at level 4 per patch, shaded with its
    /// edges, seen as in the topic's figures.
    fn default() -> Self {
        Self {
            surface: Surface::Torus,
            method: Method::Uniform,
            level: 4,
            tolerance: 0.01,
            test: Test::OneEdgeNormal,
            thresholds: Test::OneEdgeNormal.default_thresholds(),
            depth: 4,
            look: Look::Both,
            yaw: -0.5f64.to_degrees(),
            pitch: 0.67f64.to_degrees(),
            size: 480,
        }
    }
}

impl TessSetup {
    /// Keeps the set-up drawable: every number in range and finite.
    pub fn tidy(&mut self) {
        let defaults = Self::default();
        let finite_or = |v: f64, fallback: f64| if v.is_finite() { v } else { fallback };
        self.level = self.level.clamp(1, MAX_LEVEL);
        self.tolerance = finite_or(self.tolerance, defaults.tolerance).clamp(1e-5, 1.0);
        for (t, d) in self
            .thresholds
            .iter_mut()
            .zip(self.test.default_thresholds())
        {
            *t = finite_or(*t, d).clamp(1e-5, 2.0);
        }
        self.depth = self.depth.min(MAX_DEPTH);
        self.yaw = finite_or(self.yaw, defaults.yaw).clamp(-180.0, 180.0);
        self.pitch = finite_or(self.pitch, defaults.pitch).clamp(-89.0, 89.0);
        self.size = self.size.clamp(16, 2048);
    }
}

/// What a tessellation produced, drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Tessellated {
    /// The picture.
    pub canvas: Canvas,
    /// The mesh's vertices.
    pub vertices: usize,
    /// Its triangles.
    pub triangles: usize,
    /// Its vertices' positions.
    pub positions: Vec<glam::DVec3>,
    /// Their parameters on the patch grid: patch `(row, col)` covers
    /// `[col, col + 1] × [row, row + 1]`.
    pub uvs: Vec<glam::DVec2>,
}

/// Your tessellation of a set-up's surface, drawn by topic 09's renderer.
#[cfg(feature = "tessellation")]
pub(super) fn tessellate(
    setup: &TessSetup,
    decomposed: Option<&super::Decomposed>,
) -> Result<Tessellated, String> {
    use tessellation::bezier::BezierPatch;
    use tessellation::edge_tests::EdgeTest;
    use tessellation::mesh::Mesh;
    use tessellation::patch_grid::{GridPatch, PatchGrid};
    use tessellation::render::{Style, View};

    /// Every patch of `grid` by the set-up's method, in one mesh.
    fn patches<P: GridPatch>(
        grid: &PatchGrid<P>,
        setup: &TessSetup,
        test: EdgeTest,
    ) -> Result<Mesh, String> {
        let error = |e: tessellation::error::TessError| e.to_string();
        if setup.method == Method::PerPatch {
            return tessellation::per_patch::tessellate_patch_grid(grid, setup.tolerance)
                .map_err(error);
        }
        let n = setup.level as usize;
        let mut mesh = Mesh::new();
        for row in 0..grid.rows() {
            for col in 0..grid.cols() {
                let patch = grid.patch(row, col);
                let mut part =
                    tessellation::uniform::tessellate_uniform(patch, n, n).map_err(error)?;
                if setup.method == Method::FullyAdaptive {
                    part = tessellation::fully_adaptive::refine(patch, &part, test, setup.depth)
                        .map_err(error)?;
                }
                let offset = u32::try_from(mesh.positions.len()).map_err(|e| e.to_string())?;
                mesh.positions.extend(&part.positions);
                mesh.normals.extend(&part.normals);
                // Global parameters: patch (row, col) covers
                // [col, col + 1] × [row, row + 1], as topic 09's grid has it.
                let corner = glam::DVec2::new(col as f64, row as f64);
                mesh.uvs.extend(part.uvs.iter().map(|&uv| uv + corner));
                mesh.triangles
                    .extend(part.triangles.iter().map(|t| t.map(|k| k + offset)));
            }
        }
        Ok(mesh)
    }

    let [t, t2] = setup.thresholds;
    let test = match setup.test {
        Test::OneEdgeNormal => EdgeTest::OneEdgeNormal { t1: t },
        Test::OneEdgeComplementary => EdgeTest::OneEdgeComplementary { t1: t, t2 },
        Test::TwoTriangle => EdgeTest::TwoTriangle { t3: t },
        Test::FirstOrderNeighbour => EdgeTest::FirstOrderNeighbour { t3: t },
        Test::VectorDeviationFlat => EdgeTest::VectorDeviationFlat { t1: t },
        Test::LocalFlat => EdgeTest::LocalFlat { t1: t },
        Test::UmbrellaFlat => EdgeTest::UmbrellaFlat { t1: t },
    };
    let single = |patch| PatchGrid::try_new(1, 1, vec![patch]).map_err(|e| e.to_string());
    let mesh = match setup.surface {
        Surface::SeedSurface => patches(&single(BezierPatch::seed_surface())?, setup, test)?,
        Surface::Hill => patches(&single(BezierPatch::seed_hill())?, setup, test)?,
        Surface::Patches => patches(&PatchGrid::example(), setup, test)?,
        Surface::Torus => patches(&PatchGrid::torus(0.7, 0.25), setup, test)?,
        Surface::NurbsTorus | Surface::Vase => {
            let decomposed = decomposed.ok_or("the surface was not split into patches")?;
            let grid =
                PatchGrid::try_new(decomposed.rows, decomposed.cols, decomposed.patches.clone())
                    .map_err(|e| format!("your decomposition's patches: {e}"))?;
            patches(&grid, setup, test)?
        }
    };
    let style = match setup.look {
        Look::Shaded => Style::Shaded,
        Look::Wireframe => Style::Wireframe,
        Look::Both => Style::ShadedWireframe,
    };
    let view = View {
        yaw: setup.yaw.to_radians(),
        pitch: -setup.pitch.to_radians(),
    };
    Ok(Tessellated {
        canvas: tessellation::render::render(&mesh, view, style, setup.size, setup.size),
        vertices: mesh.vertex_count(),
        triangles: mesh.triangle_count(),
        positions: mesh.positions.clone(),
        uvs: mesh.uvs.clone(),
    })
}
