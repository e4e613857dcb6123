//! The transcript's events and their framing on disk. Each frame is a
//! little-endian `u32` length, then a kind byte and its payload:
//!
//! ```text
//!   Enter   0  the task function's name (UTF-8)
//!   Calls   1  batch size (u32 LE), the batch in LZ4
//!   Return  2  the values (see `evidence`)
//!   Panic   3  the message (UTF-8)
//! ```
//!
//! Consecutive callback calls travel together in one `Calls` frame,
//! compressed with LZ4: a long line hands its callbacks millions of
//! fragments that differ in a byte or two, and one frame each would cost
//! more time and disk than drawing the line. In a batch each call is its
//! parameter's position and its arguments' length (both LEB128), then the
//! arguments.

use std::io::{self, Read, Write};
use std::ops::Range;

/// The largest frame (and the largest batch, uncompressed) a replay reads:
/// a bigger length is a broken file.
pub const MAX_FRAME: u32 = 1 << 30;

/// A batch of calls is written once it holds this many bytes.
pub const BATCH_BYTES: usize = 1 << 20;

const ENTER: u8 = 0;
const CALLS: u8 = 1;
const RETURN: u8 = 2;
const PANIC: u8 = 3;

/// One step of a recorded call, as read back.
#[derive(Debug)]
pub enum Event {
    /// An outermost call of the task function with this name began.
    Enter(String),
    /// The call invoked its callback parameters (counted from 0 over all
    /// parameters) one or more times: `calls` holds each call's parameter,
    /// its arguments' length and its arguments.
    Calls(Vec<u8>),
    /// The call returned: its value and then the final value of each of
    /// its `&mut` parameters (a receiver first).
    Return(Vec<u8>),
    /// The call panicked with this message.
    Panic(String),
}

/// Writes one frame of `kind` whose payload is `parts` one after another.
fn frame(out: &mut impl Write, kind: u8, parts: &[&[u8]]) -> io::Result<()> {
    let len = 1 + parts.iter().map(|part| part.len()).sum::<usize>();
    let len = u32::try_from(len)
        .ok()
        .filter(|len| *len <= MAX_FRAME)
        .ok_or_else(|| io::Error::other("a frame too large to record"))?;
    out.write_all(&len.to_le_bytes())?;
    out.write_all(&[kind])?;
    for part in parts {
        out.write_all(part)?;
    }
    Ok(())
}

/// Writes an `Enter`.
pub fn write_enter(out: &mut impl Write, name: &str) -> io::Result<()> {
    frame(out, ENTER, &[name.as_bytes()])
}

/// Writes a `Return` of these encoded values.
pub fn write_return(out: &mut impl Write, values: &[u8]) -> io::Result<()> {
    frame(out, RETURN, &[values])
}

/// Writes a `Panic` with this message.
pub fn write_panic(out: &mut impl Write, message: &str) -> io::Result<()> {
    frame(out, PANIC, &[message.as_bytes()])
}

/// Writes a batch of calls, compressed into `room` (kept by the caller so
/// that its memory is reused).
pub fn write_calls(out: &mut impl Write, batch: &[u8], room: &mut Vec<u8>) -> io::Result<()> {
    room.resize(lz4_flex::block::get_maximum_output_size(batch.len()), 0);
    let compressed = lz4_flex::block::compress_into(batch, room).map_err(io::Error::other)?;
    let size = u32::try_from(batch.len()).map_err(io::Error::other)?;
    frame(out, CALLS, &[&size.to_le_bytes(), &room[..compressed]])
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
    if len == 0 || len > MAX_FRAME {
        return Err(io::Error::other(format!(
            "a frame of {len} bytes (1 to {MAX_FRAME})"
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
    let text = |bytes: &[u8]| String::from_utf8_lossy(bytes).into_owned();
    let payload = &bytes[1..];
    Ok(Some(match bytes[0] {
        ENTER => Event::Enter(text(payload)),
        RETURN => Event::Return(payload.to_vec()),
        PANIC => Event::Panic(text(payload)),
        CALLS => {
            let (size, compressed) = payload
                .split_first_chunk::<4>()
                .ok_or_else(|| io::Error::other("a batch of calls without its size"))?;
            let size = u32::from_le_bytes(*size);
            if size > MAX_FRAME {
                return Err(io::Error::other(format!(
                    "a batch of {size} bytes (at most {MAX_FRAME})"
                )));
            }
            let calls =
                lz4_flex::block::decompress(compressed, size as usize).map_err(io::Error::other)?;
            Event::Calls(calls)
        }
        kind => return Err(io::Error::other(format!("a frame of kind {kind}"))),
    }))
}

/// A LEB128 number appended to `out`.
fn put_len(out: &mut Vec<u8>, mut len: usize) {
    while len >= 0x80 {
        out.push((len as u8 & 0x7f) | 0x80);
        len >>= 7;
    }
    out.push(len as u8);
}

/// A LEB128 number read from `batch` at `*at`.
fn take_len(batch: &[u8], at: &mut usize) -> io::Result<usize> {
    let mut len = 0_usize;
    let mut shift = 0;
    loop {
        let byte = *batch
            .get(*at)
            .ok_or_else(|| io::Error::other("a batch of calls cut inside a number"))?;
        *at += 1;
        len |= usize::from(byte & 0x7f) << shift;
        if byte & 0x80 == 0 {
            return Ok(len);
        }
        shift += 7;
        if shift > 28 {
            return Err(io::Error::other(
                "a number out of range in a batch of calls",
            ));
        }
    }
}

/// Appends one call of callback parameter `parameter` to a batch.
pub fn push_call(batch: &mut Vec<u8>, parameter: u32, arguments: &[u8]) {
    put_len(batch, parameter as usize);
    put_len(batch, arguments.len());
    batch.extend_from_slice(arguments);
}

/// The next call in `batch` from `*at` on, its parameter and the range of
/// its arguments, moving `*at` past it; `None` at the end of the batch.
pub fn next_call(batch: &[u8], at: &mut usize) -> io::Result<Option<(u32, Range<usize>)>> {
    if *at >= batch.len() {
        return Ok(None);
    }
    let parameter = u32::try_from(take_len(batch, at)?)
        .map_err(|_| io::Error::other("a parameter out of range"))?;
    let len = take_len(batch, at)?;
    let range = *at..at.saturating_add(len);
    if range.end > batch.len() {
        return Err(io::Error::other("a batch of calls cut inside a call"));
    }
    *at = range.end;
    Ok(Some((parameter, range)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_and_batches_survive_the_round_trip_and_a_cut_file_says_so() {
        let mut batch = Vec::new();
        let nan = [0xff_u8, 0xc0, 0x7f, 0x00];
        let long = vec![7_u8; 300];
        push_call(&mut batch, 2, &nan);
        push_call(&mut batch, 3, &long);
        push_call(&mut batch, 2, &[]);
        let mut file = Vec::new();
        write_enter(&mut file, "dda_line").unwrap();
        write_calls(&mut file, &batch, &mut Vec::new()).unwrap();
        write_return(&mut file, &[1, 2]).unwrap();
        write_panic(&mut file, "not yet").unwrap();
        let mut input = file.as_slice();
        assert!(matches!(read(&mut input).unwrap(), Some(Event::Enter(n)) if n == "dda_line"));
        let Some(Event::Calls(calls)) = read(&mut input).unwrap() else {
            panic!("the second event is the batch");
        };
        let mut at = 0;
        let mut next = || {
            next_call(&calls, &mut at)
                .unwrap()
                .map(|(p, range)| (p, calls[range].to_vec()))
        };
        assert_eq!(next(), Some((2, nan.to_vec())));
        assert_eq!(next(), Some((3, long.clone())));
        assert_eq!(next(), Some((2, Vec::new())));
        assert_eq!(next(), None);
        assert!(matches!(read(&mut input).unwrap(), Some(Event::Return(v)) if v == [1, 2]));
        assert!(matches!(read(&mut input).unwrap(), Some(Event::Panic(m)) if m == "not yet"));
        assert!(read(&mut input).unwrap().is_none(), "a clean end");
        let mut input = &file[..file.len() - 1];
        for _ in 0..3 {
            read(&mut input).unwrap();
        }
        assert!(read(&mut input).is_err(), "a frame cut short is an error");
        let mut at = 0;
        assert!(
            next_call(&[0, 0x85, 1, 2], &mut at).is_err(),
            "a call cut short"
        );
        let mut junk: &[u8] = &[5, 0, 0, 0, 9, 1, 2, 3, 4];
        assert!(read(&mut junk).is_err(), "an unknown kind");
    }
}
