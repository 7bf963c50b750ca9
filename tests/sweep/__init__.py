"""Tests of electrogrowth.sweep."""
