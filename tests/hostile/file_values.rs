//! A file that is not a valid scene, named but never quoted: a wrong value in a parameter or
//! scene file is refused with its file, line, column and key; its text is shown only where it
//! reads as a number.

use super::cli_util::{stderr, stdout};
use super::run;

/// The text a refusal must not show: it stands for a password in a connection string.
const PASSWORD: &str = "PASSWORD42";

/// A wrong-typed value holding a connection string (`mu = "postgres://user:PASSWORD@host"`)
/// printed the password in the refusal, as did a list, a table, a range or a distribution
/// around it. Each is refused naming the file, its line and the key, and the password
/// appears nowhere, from `--config` and from a scene file alike.
#[test]
fn a_wrong_value_in_a_file_is_named_and_never_quoted() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let url = format!("postgres://user:{PASSWORD}@host");
    let values = [
        format!("\"{url}\""),
        format!("[\"{url}\", 1]"),
        format!("{{ a = \"{url}\" }}"),
        format!("\"0.1:{PASSWORD}\""),
        format!("\"normal({PASSWORD},1)\""),
        format!("\"\u{202e}{url}\""),
    ];
    for (i, value) in values.iter().enumerate() {
        let name = format!("p{i}.toml");
        std::fs::write(d.join(&name), format!("[scene]\nmu = {value}\n")).unwrap();
        let scene = format!("s{i}.toml");
        let chart = "[chart]\nkind = \"sweep\"\n";
        let body = format!("title = \"t\"\n[scene]\nmu = {value}\n{chart}");
        std::fs::write(d.join(&scene), body).unwrap();
        for args in [
            vec!["solve", "--config", &name],
            vec!["render", &scene, "--format", "svg", "--out", "o"],
        ] {
            let o = run(d, &args);
            let err = stderr(&o);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
            let file = args.iter().find(|a| a.ends_with(".toml")).unwrap();
            assert!(
                err.contains(&format!("{file}:")) && err.contains("mu"),
                "{err}"
            );
            assert!(!err.contains(PASSWORD), "{args:?}: {err}");
        }
    }
}

/// A number in a file is still quoted as written: it cannot hold a word.
#[test]
fn a_wrong_number_in_a_file_is_quoted() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("p.toml"), "[scene]\nradius_mm = true\n").unwrap();
    let o = run(dir.path(), &["solve", "--config", "p.toml"]);
    let err = stderr(&o);
    assert!(
        err.contains("p.toml:2:13: scene.radius_mm = true: expected a number"),
        "{err}"
    );
}

/// An environment file's key is its secret's name (`DATABASE_URL`, `API_TOKEN`): given as
/// `--config`, or as a section of a scene file, it was repeated as an unknown key. A key
/// that cannot be a setting's (lowercase letters, digits and `_`) is placed by line and
/// column but not repeated; a mistyped setting is still named, with the nearest key.
#[test]
fn a_key_that_is_no_settings_form_is_never_quoted() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (name, body) in [
        ("key.toml", format!("[scene]\n{PASSWORD} = 1\n")),
        ("section.toml", format!("[{PASSWORD}]\nx = 1\n")),
        ("nested.toml", format!("[{PASSWORD}.inner]\nx = 1\n")),
        ("env.toml", format!("{PASSWORD}_URL = \"x\"\n")),
    ] {
        std::fs::write(d.join(name), body).unwrap();
        let o = run(d, &["solve", "--config", name]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stdout(&o));
        assert!(err.contains(&format!("{name}:")), "{err}");
        assert!(err.contains("the key is not repeated"), "{err}");
        assert!(!err.contains(PASSWORD), "{name}: {err}");
    }
    std::fs::write(d.join("typo.toml"), "[scene]\nradious_mm = 3\n").unwrap();
    let o = run(d, &["solve", "--config", "typo.toml"]);
    let err = stderr(&o);
    assert!(
        err.contains("scene.radious_mm: unknown key; did you mean radius_mm?"),
        "{err}"
    );
}
