"""Deprecated: moved to roundedmesh.study.peers (issue 22).
`import roundedmesh.peers` still gives that module, with a DeprecationWarning."""
from ._deprecated import alias

alias(__name__)
