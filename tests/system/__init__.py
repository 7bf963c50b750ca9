"""Tests across every stage: the command line fuzzed, properties over the physical space,
every documentation block and gallery example, startup imports, resource limits, security,
the benchmark scripts."""
