//! The viewer's six scenes, one folder each: what it draws off the UI
//! thread (`draw`), its state in the window (`state`) and its panel and
//! picture (`ui`). A scene draws with the registry of your stages
//! ([`crate::stages`]) and the shared widgets and live drawing; no scene
//! uses another.

pub mod curves;
pub mod gpu;
pub mod mesh;
pub mod pixels;
pub mod surfaces;
pub mod tessellation;
