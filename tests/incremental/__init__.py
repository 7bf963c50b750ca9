"""Tests of electrogrowth.incremental."""
