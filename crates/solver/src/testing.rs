//! Helpers shared by the unit tests.

use std::fmt::Debug;

/// The name of the error variant each result holds, `"Ok"` for a success: the start of the
/// error's `Debug` text, up to the first space, brace or parenthesis.
pub(crate) fn variants<T, E: Debug, const N: usize>(results: [Result<T, E>; N]) -> [String; N] {
    results.map(|r| match r {
        Ok(_) => "Ok".to_string(),
        Err(e) => {
            let text = format!("{e:?}");
            text.split([' ', '{', '('])
                .next()
                .unwrap_or_default()
                .to_string()
        }
    })
}
