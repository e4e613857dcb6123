//! How values are written into a record and read back: [`Record`] and
//! [`Replay`], one value after the other: integers in LEB128 (zigzag for
//! signed ones), floats as their bytes, a list as its length and its
//! elements, a struct as its fields, an enum as its variant's number and
//! its fields.
//!
//! Why not simply `serde` bounds on the task functions: generic code is
//! compiled in the crate that uses it, here the student's, which is built
//! without optimisation; a long line's twenty million fragments then spent
//! ten times longer being encoded than being drawn. A type marked with
//! [`crate::evidence`] gets both traits implemented in its own crate (the
//! course library is optimised), so the encoding runs optimised wherever
//! the value is recorded.

/// A value a recording process writes down.
///
/// A value a task function changes through `&mut` is recorded when the
/// call ends. By default that is the whole value; a large value that a
/// task changes a little at a time (a canvas changed one fragment per
/// call) notes its changes instead ([`Record::begin_changes`],
/// [`Record::record_changes`], [`Replay::replay_changes`]; see
/// [`Changes`]), since writing a whole canvas per fragment costs the
/// square of its size.
pub trait Record {
    /// Appends the value's encoding to `out`.
    fn record(&self, out: &mut Vec<u8>);

    /// A recorded call that may change the value begins: from now on note
    /// what changes. Nothing by default.
    fn begin_changes(&mut self) {}

    /// The recorded call ends: appends what changed since
    /// [`Record::begin_changes`], in the form [`Replay::replay_changes`]
    /// reads. By default the whole value.
    fn record_changes(&mut self, out: &mut Vec<u8>) {
        self.record(out);
    }
}

/// A value a replaying process reads back.
pub trait Replay: Sized {
    /// Reads one value from the front of `input`, moving `input` past it.
    ///
    /// # Errors
    ///
    /// What does not hold a value of this type, in words.
    fn replay(input: &mut &[u8]) -> Result<Self, String>;

    /// Makes `self` what the recorded call left of its own copy, from what
    /// [`Record::record_changes`] wrote. By default the whole value.
    ///
    /// # Errors
    ///
    /// As for [`Replay::replay`]; `self` may then be changed in part.
    fn replay_changes(&mut self, input: &mut &[u8]) -> Result<(), String> {
        *self = Self::replay(input)?;
        Ok(())
    }
}

/// The journal of a large value that records its changes rather than its
/// whole self: the indices of the elements written since the recorded call
/// began, or that everything may have changed.
///
/// It lives inside the value (a canvas holds one), so it goes wherever the
/// value goes, across threads included; a value put in the place of the
/// recorded one (`*canvas = other`, or two recorded canvases swapped)
/// holds no journal begun at that place and is recorded whole. Outside a recorded call it notes nothing and costs one
/// branch per write. It takes no part in comparisons: every journal equals
/// every other, and a clone starts without one.
#[derive(Default)]
pub struct Changes(Option<Journal>);

/// The most writes a journal keeps before it says "everything".
const MAX_JOURNAL: usize = 1 << 22;

/// What a journal holds.
#[derive(Default)]
struct Journal {
    /// Where the journal was begun.
    home: usize,
    /// The elements written, in the order written (repeats included).
    written: Vec<u32>,
    /// Everything may have changed (a clear): record the whole value.
    everything: bool,
}

/// What changed during a recorded call, as [`Changes::end`] tells it.
#[derive(Debug, PartialEq, Eq)]
pub enum Changed {
    /// The value was not journaled from the call's start at its place
    /// (another value was put there), or was changed all over: record it
    /// whole.
    Whole,
    /// Only these elements may have changed: each once, in increasing
    /// order.
    Elements(Vec<u32>),
}

impl Changes {
    /// Starts a journal (a recorded call begins).
    pub fn begin(&mut self) {
        self.0 = Some(Journal {
            home: self.address(),
            ..Journal::default()
        });
    }

    /// Where this journal is: a journal found elsewhere at the call's end
    /// belongs to another value moved into the recorded one's place.
    fn address(&self) -> usize {
        std::ptr::from_ref(self) as usize
    }

    /// Element `index` is written.
    #[inline]
    pub fn note(&mut self, index: usize) {
        if let Some(journal) = &mut self.0 {
            journal.note(index);
        }
    }

    /// The elements `range` are written.
    #[inline]
    pub fn note_range(&mut self, range: std::ops::Range<usize>) {
        if let Some(journal) = &mut self.0 {
            journal.note_range(range);
        }
    }

    /// Everything may change (a clear).
    #[inline]
    pub fn note_everything(&mut self) {
        if let Some(journal) = &mut self.0 {
            journal.everything = true;
            journal.written = Vec::new();
        }
    }

    /// Ends the journal (the recorded call ends): what changed.
    pub fn end(&mut self) -> Changed {
        let here = self.address();
        match self.0.take() {
            Some(journal) if !journal.everything && journal.home == here => {
                let mut written = journal.written;
                written.sort_unstable();
                written.dedup();
                Changed::Elements(written)
            }
            _ => Changed::Whole,
        }
    }
}

// The journal's writes are kept out of line: a write to a value outside
// the grader (a benchmark, the viewer) is then one test of the journal's
// absence in a loop whose variables stay in registers; inlined, the loop
// that plots a midpoint line's pixels ran at two thirds of the speed.
impl Journal {
    #[inline(never)]
    fn note_range(&mut self, range: std::ops::Range<usize>) {
        for index in range {
            self.note(index);
        }
    }

    #[inline(never)]
    fn note(&mut self, index: usize) {
        if self.everything {
            return;
        }
        // Past a few million writes the whole value is the smaller record.
        match u32::try_from(index) {
            Ok(index) if self.written.len() < MAX_JOURNAL => self.written.push(index),
            _ => {
                self.everything = true;
                self.written = Vec::new();
            }
        }
    }
}

impl Clone for Changes {
    /// A clone is another value: no journal of the call.
    fn clone(&self) -> Self {
        Changes(None)
    }
}

impl PartialEq for Changes {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for Changes {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() { "journaled" } else { "-" })
    }
}

/// An unsigned integer in LEB128: seven bits a byte, low first, the high
/// bit saying "more" (small values, the usual case, take one byte).
fn put_varint(mut value: u128, out: &mut Vec<u8>) {
    while value >= 0x80 {
        out.push((value as u8 & 0x7f) | 0x80);
        value >>= 7;
    }
    out.push(value as u8);
}

/// An unsigned integer of at most `bits` bits read in LEB128.
fn take_varint(input: &mut &[u8], bits: u32) -> Result<u128, String> {
    let mut value = 0_u128;
    let mut shift = 0;
    loop {
        let (&byte, rest) = input
            .split_first()
            .ok_or_else(|| "the record ends inside a number".to_owned())?;
        *input = rest;
        if shift >= bits.max(7) + 7 {
            return Err("a number longer than its type".to_owned());
        }
        value |= u128::from(byte & 0x7f) << shift;
        if byte & 0x80 == 0 {
            break;
        }
        shift += 7;
    }
    if bits < 128 && value >> bits != 0 {
        return Err(format!("a number wider than {bits} bits"));
    }
    Ok(value)
}

/// The first `N` bytes of `input`, taken.
fn take_bytes<const N: usize>(input: &mut &[u8]) -> Result<[u8; N], String> {
    let (bytes, rest) = input
        .split_first_chunk::<N>()
        .ok_or_else(|| "the record ends inside a value".to_owned())?;
    *input = rest;
    Ok(*bytes)
}

macro_rules! unsigned {
    ($($ty:ty),*) => {$(
        impl Record for $ty {
            #[inline]
            fn record(&self, out: &mut Vec<u8>) {
                put_varint(*self as u128, out);
            }
        }
        impl Replay for $ty {
            #[inline]
            fn replay(input: &mut &[u8]) -> Result<Self, String> {
                let bits = <$ty>::BITS;
                take_varint(input, bits).map(|value| value as $ty)
            }
        }
    )*};
}

// Signed integers zigzagged first (0, −1, 1, −2 … → 0, 1, 2, 3 …), so a
// small negative number is a small varint too.
macro_rules! signed {
    ($($ty:ty => $unsigned:ty),*) => {$(
        impl Record for $ty {
            #[inline]
            fn record(&self, out: &mut Vec<u8>) {
                let zigzag = ((*self << 1) ^ (*self >> (<$ty>::BITS - 1))) as $unsigned;
                zigzag.record(out);
            }
        }
        impl Replay for $ty {
            #[inline]
            fn replay(input: &mut &[u8]) -> Result<Self, String> {
                let zigzag = <$unsigned>::replay(input)?;
                Ok(((zigzag >> 1) as $ty) ^ -((zigzag & 1) as $ty))
            }
        }
    )*};
}

macro_rules! float {
    ($($ty:ty),*) => {$(
        impl Record for $ty {
            #[inline]
            fn record(&self, out: &mut Vec<u8>) {
                out.extend_from_slice(&self.to_le_bytes());
            }
        }
        impl Replay for $ty {
            #[inline]
            fn replay(input: &mut &[u8]) -> Result<Self, String> {
                take_bytes(input).map(<$ty>::from_le_bytes)
            }
        }
    )*};
}

unsigned!(u8, u16, u32, u64, u128, usize);
signed!(i8 => u8, i16 => u16, i32 => u32, i64 => u64, i128 => u128, isize => usize);
float!(f32, f64);

impl Record for () {
    fn record(&self, _: &mut Vec<u8>) {}
}

impl Replay for () {
    fn replay(_: &mut &[u8]) -> Result<Self, String> {
        Ok(())
    }
}

impl Record for bool {
    fn record(&self, out: &mut Vec<u8>) {
        out.push(u8::from(*self));
    }
}

impl Replay for bool {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        match take_bytes::<1>(input)? {
            [0] => Ok(false),
            [1] => Ok(true),
            [other] => Err(format!("a truth value of {other}")),
        }
    }
}

impl Record for char {
    fn record(&self, out: &mut Vec<u8>) {
        u32::from(*self).record(out);
    }
}

impl Replay for char {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        let code = u32::replay(input)?;
        char::from_u32(code).ok_or_else(|| format!("no character has the code {code}"))
    }
}

impl Record for String {
    fn record(&self, out: &mut Vec<u8>) {
        self.as_str().record(out);
    }
}

impl Replay for String {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        let bytes = Vec::<u8>::replay(input)?;
        String::from_utf8(bytes).map_err(|_| "text that is not UTF-8".to_owned())
    }
}

// glam's vectors and matrices, the course's points and transforms, as
// their components.
macro_rules! glam_type {
    ($($ty:ty => $array:ident, $from:ident, $scalar:ty, $n:expr);*) => {$(
        impl Record for $ty {
            #[inline]
            fn record(&self, out: &mut Vec<u8>) {
                self.$array().record(out);
            }
        }
        impl Replay for $ty {
            #[inline]
            fn replay(input: &mut &[u8]) -> Result<Self, String> {
                <[$scalar; $n]>::replay(input).map(|array| <$ty>::$from(&array))
            }
        }
    )*};
}

glam_type!(
    glam::Vec2 => to_array, from_slice, f32, 2;
    glam::Vec3 => to_array, from_slice, f32, 3;
    glam::Vec4 => to_array, from_slice, f32, 4;
    glam::DVec2 => to_array, from_slice, f64, 2;
    glam::DVec3 => to_array, from_slice, f64, 3;
    glam::DVec4 => to_array, from_slice, f64, 4;
    glam::IVec2 => to_array, from_slice, i32, 2;
    glam::UVec2 => to_array, from_slice, u32, 2;
    glam::Mat3 => to_cols_array, from_cols_slice, f32, 9;
    glam::Mat4 => to_cols_array, from_cols_slice, f32, 16;
    glam::DMat3 => to_cols_array, from_cols_slice, f64, 9;
    glam::DMat4 => to_cols_array, from_cols_slice, f64, 16;
    glam::Affine3A => to_cols_array, from_cols_slice, f32, 12;
    glam::DAffine3 => to_cols_array, from_cols_slice, f64, 12
);

impl Record for str {
    fn record(&self, out: &mut Vec<u8>) {
        self.as_bytes().record(out);
    }
}

/// A message of a `&'static str` (an error's reason): kept for the rest of
/// the replaying process, which is one short test.
impl Replay for &'static str {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        String::replay(input).map(|text| &*Box::leak(text.into_boxed_str()))
    }
}

impl<T: Record + ?Sized> Record for Box<T> {
    fn record(&self, out: &mut Vec<u8>) {
        (**self).record(out);
    }
}

impl<T: Replay> Replay for Box<T> {
    fn replay(input: &mut &[u8]) -> Result<Self, String> {
        T::replay(input).map(Box::new)
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
        // On the stack: a batch of lanes is replayed millions of times.
        let mut error = None;
        let items: [Option<T>; N] = std::array::from_fn(|_| {
            if error.is_some() {
                return None;
            }
            T::replay(input).map_err(|e| error = Some(e)).ok()
        });
        match error {
            Some(error) => Err(error),
            None => Ok(items.map(|item| item.expect("every item read"))),
        }
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
    fn integers_at_their_limits_and_text_come_back() {
        round_trip((i32::MIN, i32::MAX, -1_i64, u64::MAX, i128::MIN, 0_usize));
        round_trip(('é', "ünïcode".to_owned(), true, ()));
        round_trip((glam::Vec2::new(1.0, -2.5), glam::DMat4::IDENTITY));
        let mut out = Vec::new();
        300_u32.record(&mut out);
        assert!(u8::replay(&mut out.as_slice()).is_err(), "300 is no u8");
        assert!(bool::replay(&mut [2_u8].as_slice()).is_err());
    }

    #[test]
    fn a_list_longer_than_its_bytes_is_refused() {
        let mut out = Vec::new();
        1_000_000_usize.record(&mut out);
        assert!(Vec::<u8>::replay(&mut out.as_slice()).is_err());
    }
}

#[cfg(test)]
mod journal_tests {
    use super::{Changed, Changes};

    #[test]
    fn a_journal_tells_each_element_written_once_in_order() {
        let mut changes = Changes::default();
        changes.note(3);
        assert_eq!(changes.end(), Changed::Whole, "no journal was begun");
        changes.begin();
        changes.note(7);
        changes.note_range(2..5);
        changes.note(3);
        assert_eq!(changes.end(), Changed::Elements(vec![2, 3, 4, 7]));
        assert_eq!(changes.end(), Changed::Whole, "a journal ends once");
        changes.begin();
        changes.note(1);
        changes.note_everything();
        changes.note(2);
        assert_eq!(changes.end(), Changed::Whole);
    }

    #[test]
    fn a_journal_moved_away_from_where_it_began_is_not_trusted() {
        let mut changes = Changes::default();
        changes.begin();
        changes.note(1);
        let mut moved = Box::new(std::mem::take(&mut changes));
        assert_eq!(moved.end(), Changed::Whole);
    }
}
