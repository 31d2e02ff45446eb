"""Deprecated: moved to roundedmesh.study.validation (issue 22).
`import roundedmesh.validation` still gives that module, with a DeprecationWarning."""
from ._deprecated import alias

alias(__name__)
