//! Fuzzes the voxel pop-up card text reader (design::popup::voxel::parse_voxel_card): an
//! accepted card is written back by `format_voxel_card` and reads again to the same card.
#![no_main]

use foldcam::design::popup::voxel::{format_voxel_card, parse_voxel_card};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match parse_voxel_card(text) {
        Ok(card) => {
            let again = parse_voxel_card(&format_voxel_card(&card))
                .unwrap_or_else(|e| panic!("the written card does not read back: {e}"));
            assert_eq!(again, card, "the card changed on a round trip");
        }
        Err(e) => assert!(!e.to_string().trim().is_empty()),
    }
});
