"""Deprecated: moved to roundedmesh.study.shape_error (issue 22).
`import roundedmesh.shape_error` still gives that module, with a DeprecationWarning."""
from ._deprecated import alias

alias(__name__)
