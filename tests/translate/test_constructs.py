"""Every construct of tests/fixtures/constructs.txt translates to the Python the file
gives for it (regenerate with tools/update_goldens.py and read the diff)."""
import pytest

from helpers import constructs

HEADING, CASES = constructs.read()


def test_the_fixture_file_has_cases_with_python():
    assert len(CASES) >= 40
    assert len({c.title for c in CASES}) == len(CASES)
    assert all(c.autolev and c.python for c in CASES), \
        [c.title for c in CASES if not c.python]


@pytest.mark.parametrize("case", CASES, ids=[c.title for c in CASES])
def test_a_construct_translates_as_the_fixture_says(case):
    assert constructs.written_for(case) == case.python
