"""Headless-Blender generator of probeproxy's test-level suite (see generate_suite.py)."""
