"""Deprecated: moved to roundedmesh.study.scenes (issue 22).
`import roundedmesh.scenes` still gives that module, with a DeprecationWarning."""
from ._deprecated import alias

alias(__name__)
