"""The tests mirror the package: tests/<stage>/test_<module>.py for
src/electrogrowth/<stage>/<module>.py, tests/test_<module>.py for its top-level modules, and
tests/system/ for what crosses every stage (command-line fuzzing, properties, documentation
blocks and gallery examples, startup, resource limits, security, benchmarks)."""
