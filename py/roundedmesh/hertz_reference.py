"""Deprecated: moved to roundedmesh.study.hertz_reference (issue 22).
`import roundedmesh.hertz_reference` still gives that module, with a DeprecationWarning."""
from ._deprecated import alias

alias(__name__)
