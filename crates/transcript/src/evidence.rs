//! How values are written into a record and read back: [`Record`] and
//! [`Replay`], each value in postcard's encoding, one after the other.
//!
//! Why not simply `serde` bounds on the task functions: generic code is
//! compiled in the crate that uses it, here the student's, which is built
//! without optimisation; a long line's twenty million fragments then spent
//! ten times longer being encoded than being drawn. A type marked with
//! [`crate::evidence`] gets both traits implemented in its own crate (the
//! course library is optimised), so the encoding runs optimised wherever
//! the value is recorded.

/// A value a recording process writes down.
pub trait Record {
    /// Appends the value's encoding to `out`.
    fn record(&self, out: &mut Vec<u8>);
}

/// A value a replaying process reads back.
pub trait Replay: Sized {
    /// Reads one value from the front of `input`, moving `input` past it.
    ///
    /// # Errors
    ///
    /// What does not hold a value of this type, in words.
    fn replay(input: &mut &[u8]) -> Result<Self, String>;
}

/// `value` appended to `out` by serde (what [`crate::evidence`] expands to).
pub fn encode<T: serde::Serialize + ?Sized>(value: &T, out: &mut Vec<u8>) {
    let bytes = postcard::to_extend(value, std::mem::take(out))
        .unwrap_or_else(|error| panic!("cannot record a value: {error}"));
    *out = bytes;
}

/// A value read from the front of `input` by serde.
///
/// # Errors
///
/// postcard's error, in words.
pub fn decode<T: serde::de::DeserializeOwned>(input: &mut &[u8]) -> Result<T, String> {
    let (value, rest) = postcard::take_from_bytes(input).map_err(|error| error.to_string())?;
    *input = rest;
    Ok(value)
}

macro_rules! by_serde {
    ($($ty:ty),*) => {$(
        impl Record for $ty {
            fn record(&self, out: &mut Vec<u8>) {
                encode(self, out);
            }
        }
        impl Replay for $ty {
            fn replay(input: &mut &[u8]) -> Result<Self, String> {
                decode(input)
            }
        }
    )*};
}

by_serde!(
    (),
    bool,
    char,
    u8,
    u16,
    u32,
    u64,
    u128,
    usize,
    i8,
    i16,
    i32,
    i64,
    i128,
    isize,
    f32,
    f64,
    String,
    // glam's vectors and matrices, the course's points and transforms.
    glam::Vec2,
    glam::Vec3,
    glam::Vec4,
    glam::DVec2,
    glam::DVec3,
    glam::DVec4,
    glam::IVec2,
    glam::UVec2,
    glam::Mat3,
    glam::Mat4,
    glam::DMat3,
    glam::DMat4
);

impl Record for str {
    fn record(&self, out: &mut Vec<u8>) {
        encode(self, out);
    }
}

impl<T: Record + ?Sized> Record for &T {
    fn record(&self, out: &mut Vec<u8>) {
        (**self).record(out);
    }
}

impl<T: Record + ?Sized> Record for &mut T {
    fn record(&self, out: &mut Vec<u8>) {
        (**self).record(out);
    }
}

impl<T: Record> Record for [T] {
    fn record(&self, out: &mut Vec<u8>) {
        self.len().record(out);
        for item in self {
            item.record(out);
        }
    }
}

impl<T: Record> Record for Vec<T> {
    fn record(&self, out: &mut Vec<u8>) {
        self.as_slice().record(out);
    }
}

impl<T: Replay> Replay for Vec<T> {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        let len = usize::replay(input)?;
        // Every value takes a byte at least: a longer claim is a lie.
        if len > input.len() {
            return Err(format!("a list of {len} values in {} bytes", input.len()));
        }
        (0..len).map(|_| T::replay(input)).collect()
    }
}

impl<T: Record, const N: usize> Record for [T; N] {
    fn record(&self, out: &mut Vec<u8>) {
        for item in self {
            item.record(out);
        }
    }
}

impl<T: Replay, const N: usize> Replay for [T; N] {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        let items: Vec<T> = (0..N).map(|_| T::replay(input)).collect::<Result<_, _>>()?;
        items
            .try_into()
            .map_err(|_| "an array of the wrong length".to_owned())
    }
}

impl<T: Record> Record for Option<T> {
    fn record(&self, out: &mut Vec<u8>) {
        match self {
            None => out.push(0),
            Some(value) => {
                out.push(1);
                value.record(out);
            }
        }
    }
}

impl<T: Replay> Replay for Option<T> {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        match u8::replay(input)? {
            0 => Ok(None),
            1 => T::replay(input).map(Some),
            tag => Err(format!("an option tagged {tag}")),
        }
    }
}

impl<T: Record, E: Record> Record for Result<T, E> {
    fn record(&self, out: &mut Vec<u8>) {
        match self {
            Ok(value) => {
                out.push(0);
                value.record(out);
            }
            Err(error) => {
                out.push(1);
                error.record(out);
            }
        }
    }
}

impl<T: Replay, E: Replay> Replay for Result<T, E> {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        match u8::replay(input)? {
            0 => T::replay(input).map(Ok),
            1 => E::replay(input).map(Err),
            tag => Err(format!("a result tagged {tag}")),
        }
    }
}

macro_rules! tuples {
    ($(($($name:ident),+)),*) => {$(
        impl<$($name: Record),+> Record for ($($name,)+) {
            #[allow(non_snake_case)]
            fn record(&self, out: &mut Vec<u8>) {
                let ($($name,)+) = self;
                $($name.record(out);)+
            }
        }
        impl<$($name: Replay),+> Replay for ($($name,)+) {
            fn replay(input: &mut &[u8]) -> Result<Self, String> {
                Ok(($($name::replay(input)?,)+))
            }
        }
    )*};
}

tuples!(
    (A),
    (A, B),
    (A, B, C),
    (A, B, C, D),
    (A, B, C, D, E),
    (A, B, C, D, E, F)
);

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trip<T: Record + Replay + PartialEq + std::fmt::Debug>(value: T) {
        let mut out = Vec::new();
        value.record(&mut out);
        let mut input = out.as_slice();
        assert_eq!(T::replay(&mut input).unwrap(), value);
        assert!(input.is_empty(), "{value:?} read to its end");
    }

    #[test]
    fn values_come_back_as_they_went() {
        round_trip((1_u32, -2_i64, 0.5_f32));
        round_trip(vec![Some(3_u8), None]);
        round_trip([1.5_f64, f64::INFINITY, -0.0]);
        round_trip(Ok::<String, u8>("pixel".into()));
        round_trip(Err::<String, u8>(7));
        let mut out = Vec::new();
        f32::NAN.record(&mut out);
        assert!(f32::replay(&mut out.as_slice()).unwrap().is_nan());
    }

    #[test]
    fn a_list_longer_than_its_bytes_is_refused() {
        let mut out = Vec::new();
        1_000_000_usize.record(&mut out);
        assert!(Vec::<u8>::replay(&mut out.as_slice()).is_err());
    }
}
