# Models that live in the test tree (none yet).
