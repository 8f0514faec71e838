//! Layer 2: the reusable numerical pieces the methods are built from. Each is tested against a
//! slow, obvious oracle.

pub mod box_sum;
pub mod distance;
pub mod fft;
pub mod fft_ssd;
pub mod maxflow;
pub mod nn;
pub mod poisson;
pub mod tps;
pub mod wavelet;
