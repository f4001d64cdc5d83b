//! The licence `Cargo.toml` declares is shipped as text: each licence of
//! the `license` expression has its file at the top of the repository, and
//! the README names each file.

use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The licences of the SPDX expression in `Cargo.toml` (`A OR B`).
fn declared() -> Vec<String> {
    let manifest = std::fs::read_to_string(root().join("Cargo.toml")).expect("Cargo.toml");
    let line = manifest
        .lines()
        .find(|l| l.trim_start().starts_with("license ="))
        .expect("Cargo.toml declares a licence");
    let expr = line.split('"').nth(1).expect("a quoted SPDX expression");
    expr.split(" OR ").map(|s| s.trim().to_string()).collect()
}

/// The file the Rust ecosystem's convention names for an SPDX identifier.
fn file_for(spdx: &str) -> String {
    match spdx {
        "Apache-2.0" => "LICENSE-APACHE".to_string(),
        other => format!("LICENSE-{other}"),
    }
}

/// A phrase that each licence's standard text contains.
fn marker(spdx: &str) -> &'static str {
    match spdx {
        "MIT" => "Permission is hereby granted, free of charge",
        "Apache-2.0" => "Apache License\n                           Version 2.0, January 2004",
        other => panic!("no text known for {other}"),
    }
}

#[test]
fn every_declared_licence_has_its_text_and_the_readme_names_it() {
    let licences = declared();
    assert!(licences.len() >= 2, "{licences:?}");
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    for spdx in &licences {
        let name = file_for(spdx);
        let text = std::fs::read_to_string(root().join(&name))
            .unwrap_or_else(|e| panic!("{name} for {spdx}: {e}"));
        assert!(text.contains(marker(spdx)), "{name} is not the {spdx} text");
        assert!(text.contains("Copyright (c) the cop authors"), "{name}");
        assert!(
            readme.contains(&format!("({name})")),
            "README does not link {name}"
        );
    }
}
