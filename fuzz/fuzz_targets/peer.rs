#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    openr_fuzz_checks::peer(data);
});
