//! Peak resident memory of this process, for the listing's final block.

/// The most memory this process has held resident so far, in bytes
/// (getrusage's ru_maxrss, which Linux gives in KiB); 0 where it cannot say.
pub(super) fn peak_resident_bytes() -> f64 {
    // SAFETY: rusage is plain old data; getrusage fills the struct it is
    // given and touches nothing else.
    let mut u: libc::rusage = unsafe { std::mem::zeroed() };
    let r = unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut u) };
    if r != 0 {
        return 0.0;
    }
    u.ru_maxrss as f64 * 1024.0
}

#[cfg(test)]
mod tests {
    /// A fresh 64 MiB block, touched page by page, shows in the peak.
    #[test]
    fn the_peak_sees_what_was_touched() {
        let before = super::peak_resident_bytes();
        assert!(before > 0.0);
        let block = vec![1u8; 64 << 20];
        let after = super::peak_resident_bytes();
        assert!(
            after >= before.max(64.0 * 1024.0 * 1024.0),
            "{before} -> {after}"
        );
        assert_eq!(block.iter().map(|&b| b as usize).sum::<usize>(), 64 << 20);
    }
}
