"""Deprecated: moved to roundedmesh.study.model_choice (issue 22).
`import roundedmesh.model_choice` still gives that module, with a DeprecationWarning."""
from ._deprecated import alias

alias(__name__)
