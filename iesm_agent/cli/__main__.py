"""`python -m iesm_agent.cli` == `iesm`."""

from . import main

main()
