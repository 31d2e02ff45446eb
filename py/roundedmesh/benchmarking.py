"""Deprecated: moved to roundedmesh.study.benchmarking (issue 22).
`import roundedmesh.benchmarking` still gives that module, with a DeprecationWarning."""
from ._deprecated import alias

alias(__name__)
