"""Deprecated: moved to roundedmesh.study.analytic (issue 22).
`import roundedmesh.analytic` still gives that module, with a DeprecationWarning."""
from ._deprecated import alias

alias(__name__)
