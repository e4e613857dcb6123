//! The staff's class: a generated class to try grading on
//! ([`generated`]).

pub mod generated;
