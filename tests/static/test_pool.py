"""The static engine's workers: a run folder that cannot be written (a full disk, a vanished or
pseudo file system) is that run's failure with the system's reason, and the worker serves on."""

from __future__ import annotations

from pathlib import Path

from yadearch.case.config import preset
from yadearch.static.pool import run_static, stop_workers


def test_a_folder_that_cannot_be_written_is_a_failure_with_its_reason(tmp_path: Path) -> None:
    case_file = tmp_path / "case.toml"
    case_file.write_text(preset("set2").with_overrides({"engine": "static", "n_voussoirs": 9}).to_toml())
    try:
        code, message = run_static(case_file, Path("/proc/yadearch/staging"), timeout_s=120)
        assert code == 1 and "cannot write the run folder" in message and "\n" not in message.strip()
        code, message = run_static(case_file, tmp_path / "staging", timeout_s=120)  # the same worker serves on
        assert (tmp_path / "staging" / "summary.json").is_file(), message
    finally:
        stop_workers()
