//! The transcript's events and their framing on disk: each frame is a
//! little-endian `u32` length followed by that many bytes of an [`Event`]
//! in postcard's encoding (exact for every float, NaN and infinities too).
//!
//! Consecutive calls of one callback parameter travel together in one
//! [`Event::Calls`] frame, compressed with LZ4: a long line hands its
//! callback millions of fragments that differ in a byte or two, and one
//! frame each would cost more time and disk than drawing the line.

use std::io::{self, Read, Write};

use serde::{Deserialize, Serialize};

/// The largest frame (and the largest batch, uncompressed) a replay reads:
/// a bigger length is a broken file.
pub const MAX_FRAME: u32 = 1 << 30;

/// A batch of calls is written once it holds this many bytes.
pub const BATCH_BYTES: usize = 1 << 20;

/// One step of a recorded call.
#[derive(Debug, Serialize, Deserialize)]
pub enum Event {
    /// An outermost call of the task function with this name began.
    Enter(String),
    /// The call invoked its callback parameter number `parameter` (counted
    /// from 0 over all parameters) one or more times: `calls` is the LZ4
    /// block (its size prepended) of the arguments of each call, each a
    /// tuple in postcard's encoding after its length as a postcard varint.
    Calls {
        /// The parameter's position.
        parameter: u32,
        /// The compressed arguments.
        calls: Vec<u8>,
    },
    /// The call returned: its value and then the final value of each of
    /// its `&mut` parameters (a receiver first), encoded as a tuple.
    Return(Vec<u8>),
    /// The call panicked with this message.
    Panic(String),
}

/// Writes `event` as one frame.
pub fn write(out: &mut impl Write, event: &Event) -> io::Result<()> {
    let bytes = postcard::to_stdvec(event).map_err(io::Error::other)?;
    let len = u32::try_from(bytes.len())
        .ok()
        .filter(|len| *len <= MAX_FRAME)
        .ok_or_else(|| io::Error::other("event too large to record"))?;
    out.write_all(&len.to_le_bytes())?;
    out.write_all(&bytes)
}

/// Reads the next frame: `Ok(None)` at a clean end of the file.
pub fn read(input: &mut impl Read) -> io::Result<Option<Event>> {
    let mut len = [0_u8; 4];
    match input.read_exact(&mut len) {
        Ok(()) => {}
        Err(error) if error.kind() == io::ErrorKind::UnexpectedEof => return Ok(None),
        Err(error) => return Err(error),
    }
    let len = u32::from_le_bytes(len);
    if len > MAX_FRAME {
        return Err(io::Error::other(format!(
            "a frame of {len} bytes (at most {MAX_FRAME})"
        )));
    }
    let mut bytes = Vec::new();
    input.take(u64::from(len)).read_to_end(&mut bytes)?;
    if bytes.len() != len as usize {
        return Err(io::Error::new(
            io::ErrorKind::UnexpectedEof,
            "the transcript ends inside a frame",
        ));
    }
    postcard::from_bytes(&bytes)
        .map(Some)
        .map_err(io::Error::other)
}

/// Appends one call's encoded arguments to a batch.
pub fn push_call(batch: &mut Vec<u8>, arguments: &[u8]) {
    let mut len = arguments.len();
    // postcard's varint: seven bits a byte, the high bit says "more".
    while len >= 0x80 {
        batch.push((len as u8 & 0x7f) | 0x80);
        len >>= 7;
    }
    batch.push(len as u8);
    batch.extend_from_slice(arguments);
}

/// The batch of calls as an [`Event::Calls`].
pub fn calls(parameter: u32, batch: &[u8]) -> Event {
    Event::Calls {
        parameter,
        calls: lz4_flex::block::compress_prepend_size(batch),
    }
}

/// The calls of a batch, uncompressed.
pub fn uncompress(calls: &[u8]) -> io::Result<Vec<u8>> {
    let size = calls
        .get(..4)
        .map(|size| u32::from_le_bytes([size[0], size[1], size[2], size[3]]))
        .ok_or_else(|| io::Error::other("a batch of calls without its size"))?;
    if size > MAX_FRAME {
        return Err(io::Error::other(format!(
            "a batch of {size} bytes (at most {MAX_FRAME})"
        )));
    }
    lz4_flex::block::decompress_size_prepended(calls).map_err(io::Error::other)
}

/// The next call's arguments in `batch` from `*at` on, moving `*at` past
/// them; `None` at the end of the batch.
pub fn next_call<'a>(batch: &'a [u8], at: &mut usize) -> io::Result<Option<&'a [u8]>> {
    if *at >= batch.len() {
        return Ok(None);
    }
    let mut len = 0_usize;
    let mut shift = 0;
    loop {
        let byte = *batch
            .get(*at)
            .ok_or_else(|| io::Error::other("a batch of calls cut inside a length"))?;
        *at += 1;
        len |= usize::from(byte & 0x7f)
            .checked_shl(shift)
            .ok_or_else(|| io::Error::other("a call's length out of range"))?;
        if byte & 0x80 == 0 {
            break;
        }
        shift += 7;
        if shift > 28 {
            return Err(io::Error::other("a call's length out of range"));
        }
    }
    let call = batch
        .get(*at..at.saturating_add(len))
        .ok_or_else(|| io::Error::other("a batch of calls cut inside a call"))?;
    *at += len;
    Ok(Some(call))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_and_batches_survive_the_round_trip_and_a_cut_file_says_so() {
        let mut batch = Vec::new();
        let nan = postcard::to_stdvec(&(f32::NAN, f64::NEG_INFINITY)).unwrap();
        let long = vec![7_u8; 300];
        for call in [&nan[..], &long[..], &[][..]] {
            push_call(&mut batch, call);
        }
        let mut file = Vec::new();
        write(&mut file, &Event::Enter("dda_line".into())).unwrap();
        write(&mut file, &calls(2, &batch)).unwrap();
        let mut input = file.as_slice();
        assert!(matches!(read(&mut input).unwrap(), Some(Event::Enter(n)) if n == "dda_line"));
        let Some(Event::Calls {
            parameter: 2,
            calls,
        }) = read(&mut input).unwrap()
        else {
            panic!("the second event is the batch");
        };
        let batch = uncompress(&calls).unwrap();
        let mut at = 0;
        let first = next_call(&batch, &mut at).unwrap().unwrap();
        let (a, b): (f32, f64) = postcard::from_bytes(first).unwrap();
        assert!(a.is_nan() && b == f64::NEG_INFINITY, "floats kept exactly");
        assert_eq!(next_call(&batch, &mut at).unwrap(), Some(&long[..]));
        assert_eq!(next_call(&batch, &mut at).unwrap(), Some(&[][..]));
        assert_eq!(next_call(&batch, &mut at).unwrap(), None);
        assert!(read(&mut input).unwrap().is_none(), "a clean end");
        let mut input = &file[..file.len() - 1];
        read(&mut input).unwrap();
        assert!(read(&mut input).is_err(), "a frame cut short is an error");
        let mut at = 0;
        assert!(
            next_call(&[0x85, 1, 2], &mut at).is_err(),
            "a call cut short"
        );
    }
}
