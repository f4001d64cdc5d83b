#!/usr/bin/env python3
"""Tests of mutants.py (run by `scripts/test.sh lint`): the cfg gate of a
survivor, the update of recorded survivors by a limited run, and entries of
the equivalent list that name a line."""
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).parent))
import mutants  # noqa: E402

SCRIPT = pathlib.Path(__file__).parent / "mutants.py"
SOURCE = """\
impl Srdo {
    fn poll(&mut self) -> bool {
        a && b
    }

    /// Static mapping only.
    #[cfg(srdo_static_mapping)]
    pub fn fields(&mut self) -> CopResult {
        self.slot()?;
        Ok(())
    }
}
"""
POLL = "src/x.rs:3:11: replace && with || in Srdo::poll"
FIELDS = "src/x.rs:9:9: replace Srdo::fields -> CopResult with Default::default()"


class CfgTest(unittest.TestCase):
    def test_predicates(self):
        cfgs = {"srdo_use_gfc", 'feature="std"'}
        self.assertTrue(mutants.cfg_holds("srdo_use_gfc", cfgs))
        self.assertFalse(mutants.cfg_holds("srdo_static_mapping", cfgs))
        self.assertTrue(mutants.cfg_holds("not(srdo_static_mapping)", cfgs))
        self.assertTrue(mutants.cfg_holds('all(srdo_use_gfc, feature = "std")', cfgs))
        self.assertFalse(mutants.cfg_holds("all(srdo_use_gfc, srdo_static_mapping)", cfgs))
        self.assertTrue(mutants.cfg_holds("any(srdo_static_mapping, srdo_use_gfc)", cfgs))

    def test_config_of_a_run(self):
        names = {"default": set(), "variant-a": set(), "variant-b": set()}
        self.assertEqual(mutants.config_of("wire-srdo-variant-a", names), "variant-a")
        self.assertEqual(mutants.config_of("srdo-mod-default-tail", names), "default")
        self.assertIsNone(mutants.config_of("check", names))


class CombineTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.root = pathlib.Path(self.dir.name)
        (self.root / "src").mkdir()
        (self.root / "src/x.rs").write_text(SOURCE)
        self.runs = self.root / "runs"
        self.runs.mkdir()
        (self.runs / "cfg-default.txt").write_text("srdo_use_gfc\n")
        (self.runs / "cfg-variant-a.txt").write_text("srdo_use_gfc\nsrdo_static_mapping\n")
        self.out = self.root / "mutants.json"
        self.equiv = self.root / "equivalent.toml"
        self.equiv.write_text("")

    def tearDown(self):
        self.dir.cleanup()

    def outcome(self, config, outcome, *lines, kind=""):
        d = self.runs / f"x-{config}{kind}" / "mutants.out"
        d.mkdir(parents=True, exist_ok=True)
        (d / f"{outcome}.txt").write_text("".join(line + "\n" for line in lines))

    def record_one_survivor(self):
        """A result before: 10 caught, the && of `poll` missed."""
        survivor = {"file": "src/x.rs", "line": 3, "mutant": "replace && with || in Srdo::poll", "argument": None}
        figures = {"caught": 10, "timeout": 0, "missed": 1, "unviable": 0, "equivalent": 0}
        self.out.write_text(json.dumps({"runs": {}, "files": {"src/x.rs": figures}, "survivors": [survivor]}))

    def combine(self):
        p = subprocess.run([sys.executable, str(SCRIPT), str(self.runs), str(self.out), str(self.equiv)],
                           cwd=self.root, capture_output=True, text=True)
        return p.returncode, json.loads(self.out.read_text())

    def test_a_survivor_where_its_function_is_compiled_out_is_not_counted(self):
        self.outcome("default", "missed", FIELDS)
        self.outcome("default", "caught", POLL)
        self.outcome("variant-a", "unviable", FIELDS)
        self.outcome("variant-a", "caught", POLL)
        rc, result = self.combine()
        self.assertEqual(rc, 0, result)
        self.assertEqual(result["files"]["src/x.rs"]["unviable"], 1)
        self.assertEqual(result["files"]["src/x.rs"]["missed"], 0)

    def test_a_survivor_where_its_function_is_built_fails(self):
        self.outcome("variant-a", "missed", FIELDS)
        rc, result = self.combine()
        self.assertEqual(rc, 1)
        self.assertEqual([s["line"] for s in result["survivors"]], [9])

    def test_a_run_of_the_recorded_survivors_updates_them_only(self):
        recorded = {"runs": {"x-default": {"caught": 40, "missed": 2}},
                    "files": {"src/x.rs": {"caught": 40, "timeout": 0, "missed": 2, "unviable": 5,
                                           "equivalent": 0}},
                    "survivors": [{"file": "src/x.rs", "line": 3, "mutant": "replace && with || in Srdo::poll",
                                   "argument": None},
                                  {"file": "src/x.rs", "line": 9,
                                   "mutant": "replace Srdo::fields -> CopResult with Default::default()",
                                   "argument": None}]}
        self.out.write_text(json.dumps(recorded))
        self.outcome("default", "caught", POLL, kind="-survivors")
        self.outcome("default", "missed", FIELDS, kind="-survivors")
        rc, result = self.combine()
        # The mutant of `fields` ran only where it is compiled out: still a
        # survivor (variant-a, which builds it, did not run).
        self.assertEqual(rc, 1)
        self.assertEqual(result["files"]["src/x.rs"],
                         {"caught": 41, "timeout": 0, "missed": 1, "unviable": 5, "equivalent": 0})
        self.assertEqual(sorted(result["runs"]), ["x-default", "x-default-survivors"])
        self.outcome("variant-a", "unviable", FIELDS, kind="-survivors")
        rc, result = self.combine()
        self.assertEqual(rc, 0)
        self.assertEqual(result["files"]["src/x.rs"],
                         {"caught": 41, "timeout": 0, "missed": 0, "unviable": 6, "equivalent": 0})

    def test_a_caught_mutant_outside_the_survivors_is_left_as_recorded(self):
        self.record_one_survivor()
        self.outcome("default", "caught", POLL, "src/x.rs:2:5: replace Srdo::poll -> bool with true",
                     kind="-survivors")
        rc, result = self.combine()
        self.assertEqual(rc, 0)
        self.assertEqual(result["files"]["src/x.rs"]["caught"], 11)
        # Missed there, it is a survivor the base does not know: fails.
        self.outcome("default", "missed", "src/x.rs:2:5: replace Srdo::poll -> bool with false",
                     kind="-survivors")
        rc, result = self.combine()
        self.assertEqual(rc, 1)
        self.assertEqual(result["files"]["src/x.rs"]["caught"], 11)

    def test_a_complete_run_replaces_the_figures(self):
        self.record_one_survivor()
        self.outcome("default", "caught", POLL)
        rc, result = self.combine()
        self.assertEqual(rc, 0)
        self.assertEqual(result["files"]["src/x.rs"]["caught"], 1)
        self.assertNotIn("base", result)

    def test_an_equivalent_entry_with_a_line_explains_that_line_only(self):
        other = "src/x.rs:2:20: replace && with || in Srdo::poll"
        self.outcome("default", "missed", POLL, other)
        self.equiv.write_text('[[equivalent]]\nfile = "src/x.rs"\nmutant = "replace && with || in Srdo::poll"\n'
                              'line = 3\nargument = "a and b are equal"\n')
        rc, result = self.combine()
        self.assertEqual(rc, 1)
        self.assertEqual(result["files"]["src/x.rs"]["equivalent"], 1)
        self.assertEqual([(s["line"], s["argument"]) for s in result["survivors"]],
                         [(2, None), (3, "a and b are equal")])


if __name__ == "__main__":
    os.chdir(pathlib.Path(__file__).parent)
    unittest.main()
