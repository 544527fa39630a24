//! Generic frictional multi-contact impact of planar rigid bodies, solved as the LCP of spec §8.
//!
//! (Filled in by the single-impact work item.)
