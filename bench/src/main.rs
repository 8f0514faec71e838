//! `compare`: speed and quality of texsynth's methods side by side with the texture-synthesis crate.
//! (Work in progress.)

fn main() {
    let _ = texture_synthesis::Dims::square(4);
}
