//! The course side of grading a class on GitHub Actions, spread over
//! machines: `.github/workflows/grade-class.yml`, which `cargo xtask
//! release --classroom` writes beside the Classroom workflow.
//!
//! Run by hand in the course's own repository (it does nothing in a
//! student's copy), it reads a roster of the members' repositories, one
//! `owner/name` a line, and grades the class as a matrix of shards, each
//! machine its part (`cargo xtask grade --submission class --shard I/N`);
//! a last job joins the parts (`cargo xtask gradebook merge`) and keeps
//! the class's grade as the artifact `class-grade`: every member's report,
//! the gradebook and the class's report.
//!
//! ```text
//!   plan ──> grade (shard 1) ──┐
//!        ──> grade (shard 2) ──┼──> merge ──> artifact class-grade
//!        ──> grade (shard N) ──┘
//! ```

use crate::staff::classroom::CourseRepo;

/// The file the workflow is written to, relative to the edition.
pub const WORKFLOW: &str = ".github/workflows/grade-class.yml";

/// The most machines a class is spread over.
pub const MAX_SHARDS: usize = 20;

/// `.github/workflows/grade-class.yml` for the course repository `course`.
#[must_use]
pub fn workflow(course: &CourseRepo) -> String {
    let repository = &course.repository;
    let install = r"      - name: Install the sandbox and the software GPU driver
        run: |
          sudo apt-get update -q
          sudo apt-get install -y -q bubblewrap mesa-vulkan-drivers libvulkan1
          # Ubuntu 24.04 keeps unprivileged user namespaces, bubblewrap's
          # sandbox, from programs without an AppArmor profile.
          sudo sysctl -w kernel.apparmor_restrict_unprivileged_userns=0 || true
      - name: Install Rust
        run: rustup toolchain install stable --profile minimal && rustup default stable
";
    format!(
        r#"# Written by `cargo xtask release --classroom`: grades a class, spread over
# several machines. Run it by hand in the course's repository ({repository}):
# Actions, "Grade a class", "Run workflow". The roster is a file of this
# repository listing the members' repositories, one owner/name a line (`#`
# starts a comment); the secret CLASS_TOKEN, a token that can read them,
# is needed where they are private. Each machine grades its part of the
# class (`cargo xtask grade --submission class --shard I/N`), and the last
# job joins the parts (`cargo xtask gradebook merge`) into the artifact
# class-grade: every member's report, gradebook.csv and the class's report.
name: Grade a class
on:
  workflow_dispatch:
    inputs:
      roster:
        description: "The roster: a file of this repository, one member's repository (owner/name) a line"
        required: true
        default: roster.txt
      shards:
        description: "How many machines grade the class (1 to {MAX_SHARDS})"
        required: true
        default: "4"
permissions:
  contents: read
jobs:
  plan:
    if: github.repository == '{repository}'
    runs-on: ubuntu-latest
    outputs:
      shards: ${{{{ steps.shards.outputs.list }}}}
      count: ${{{{ steps.shards.outputs.count }}}}
    steps:
      - name: The shards
        id: shards
        env:
          SHARDS: ${{{{ inputs.shards }}}}
        run: |
          if ! [[ "$SHARDS" =~ ^[0-9]+$ ]] || [ "$SHARDS" -lt 1 ] || [ "$SHARDS" -gt {MAX_SHARDS} ]; then
            echo "::error::shards is a number from 1 to {MAX_SHARDS}, not '$SHARDS'"
            exit 1
          fi
          echo "list=[$(seq -s, 1 "$SHARDS")]" >> "$GITHUB_OUTPUT"
          echo "count=$SHARDS" >> "$GITHUB_OUTPUT"
  grade:
    needs: plan
    runs-on: ubuntu-latest
    timeout-minutes: 360
    strategy:
      fail-fast: false
      matrix:
        shard: ${{{{ fromJSON(needs.plan.outputs.shards) }}}}
    steps:
      - name: Check out the course
        uses: actions/checkout@v4
        with:
          path: course
{install}      - name: Clone the class
        env:
          ROSTER: course/${{{{ inputs.roster }}}}
          TOKEN: ${{{{ secrets.CLASS_TOKEN || github.token }}}}
        run: |
          mkdir class
          repositories() {{
            while IFS= read -r line || [ -n "$line" ]; do
              repository="$(printf '%s' "${{line%%#*}}" | tr -d '[:space:]')"
              if [ -n "$repository" ]; then printf '%s\n' "$repository"; fi
            done < "$ROSTER"
          }}
          # A member's folder is its repository's name; where the roster
          # names more than one owner, owner--name, so that two owners'
          # repositories of one name are two members.
          owners="$(repositories | sed 's|/.*||' | sort -u | wc -l)"
          while IFS= read -r repository; do
            folder="${{repository##*/}}"
            [ "$owners" -gt 1 ] && folder="${{repository%%/*}}--$folder"
            if [ -e "class/$folder" ]; then
              echo "::error::$repository is on the roster twice (its folder class/$folder is taken)"
              continue
            fi
            git clone --quiet --depth 1 "https://x-access-token:$TOKEN@github.com/$repository.git" "class/$folder" </dev/null \
              || echo "::warning::cannot clone $repository"
          done < <(repositories)
          echo "$(find class -mindepth 1 -maxdepth 1 -type d | wc -l) member(s) cloned"
      - name: Grade this shard
        working-directory: course
        env:
          SHARD: ${{{{ matrix.shard }}}}/${{{{ needs.plan.outputs.count }}}}
        run: |
{delegate}          cargo xtask grade --submission ../class --shard "$SHARD" --out ../part || echo "::warning::some members of shard $SHARD could not be graded (see their lines above)"
      - name: Keep the part
        uses: actions/upload-artifact@v4
        with:
          name: part-${{{{ matrix.shard }}}}
          path: part/
          if-no-files-found: error
  merge:
    needs: grade
    if: ${{{{ !cancelled() && needs.grade.result != 'skipped' }}}}
    runs-on: ubuntu-latest
    steps:
      - name: Check out the course
        uses: actions/checkout@v4
        with:
          path: course
      - name: Install Rust
        run: rustup toolchain install stable --profile minimal && rustup default stable
      - name: Fetch the parts
        uses: actions/download-artifact@v4
        with:
          pattern: part-*
          path: parts
      - name: Join the parts
        working-directory: course
        run: cargo xtask gradebook merge ../parts/part-* --out ../class-grade
      - name: Keep the class's grade
        if: always()
        uses: actions/upload-artifact@v4
        with:
          name: class-grade
          path: class-grade/
"#,
        delegate = crate::sandbox::delegate_script("          "),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_workflow_grades_shards_and_merges_them_in_the_course_only() {
        let course: CourseRepo = "teach/raster@v1".parse().unwrap();
        let yaml = workflow(&course);
        assert!(yaml.contains("if: github.repository == 'teach/raster'"));
        assert!(yaml.contains("--shard \"$SHARD\" --out ../part"));
        assert!(yaml.contains("cargo xtask gradebook merge ../parts/part-* --out ../class-grade"));
        assert!(yaml.contains("shard: ${{ fromJSON(needs.plan.outputs.shards) }}"));
        assert!(
            !yaml.contains("${{{") && !yaml.contains("{MAX_SHARDS}"),
            "{yaml}"
        );
    }

    /// The script of the step `step` of `yaml`, as bash gets it.
    #[cfg(unix)]
    fn script(yaml: &str, step: &str) -> String {
        let from = yaml.find(&format!("- name: {step}\n")).expect("the step");
        let run = from + yaml[from..].find("run: |\n").expect("its script") + "run: |\n".len();
        yaml[run..]
            .lines()
            .take_while(|line| line.is_empty() || line.starts_with("          "))
            .map(|line| line.get(10..).unwrap_or(""))
            .collect::<Vec<_>>()
            .join("\n")
    }

    /// Two owners' repositories of one name are two members (a member
    /// once took a classmate's row by naming a repository like theirs),
    /// and a repository twice on the roster is cloned once.
    #[cfg(unix)]
    #[test]
    fn the_class_is_cloned_into_a_folder_for_each_repository() {
        let dir = crate::files::tests::scratch("clone-class");
        let bin = dir.join("bin");
        std::fs::create_dir(&bin).unwrap();
        // git clone --quiet --depth 1 URL FOLDER: the folder, with the URL.
        crate::files::write_file(
            &bin.join("git"),
            "#!/bin/sh\nmkdir \"$6\" && echo \"$5\" > \"$6/url\"\n",
        )
        .unwrap();
        std::fs::set_permissions(
            bin.join("git"),
            std::os::unix::fs::PermissionsExt::from_mode(0o755),
        )
        .unwrap();
        let clone = |roster: &str| -> (Vec<String>, String) {
            let _ = crate::files::remove_tree(&dir.join("class"));
            std::fs::write(dir.join("roster.txt"), roster).unwrap();
            let run = std::process::Command::new("bash")
                // As GitHub runs a step's script: `bash -eo pipefail`.
                .args([
                    "-eo",
                    "pipefail",
                    "-c",
                    &script(
                        &workflow(&"teach/raster".parse().unwrap()),
                        "Clone the class",
                    ),
                ])
                .current_dir(&dir)
                .env("ROSTER", dir.join("roster.txt"))
                .env("TOKEN", "t")
                .env(
                    "PATH",
                    format!("{}:{}", bin.display(), std::env::var("PATH").unwrap()),
                )
                .output()
                .unwrap();
            assert!(
                run.status.success(),
                "{}",
                String::from_utf8_lossy(&run.stderr)
            );
            let mut folders: Vec<String> = std::fs::read_dir(dir.join("class"))
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect();
            folders.sort();
            (folders, String::from_utf8_lossy(&run.stdout).into_owned())
        };
        let (folders, said) =
            clone("alice/raster\n# a note\n\n bob/raster # Bob\nalice/raster\n# the end\n");
        assert_eq!(folders, ["alice--raster", "bob--raster"], "{said}");
        assert!(
            said.contains("::error::alice/raster is on the roster twice"),
            "{said}"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("class/bob--raster/url"))
                .unwrap()
                .trim(),
            "https://x-access-token:t@github.com/bob/raster.git"
        );
        let (folders, _) = clone("org/raster-anna\norg/raster-ben");
        assert_eq!(
            folders,
            ["raster-anna", "raster-ben"],
            "one owner: the repositories' names"
        );
        crate::files::remove_tree(&dir).unwrap();
    }
}
