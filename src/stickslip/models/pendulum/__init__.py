"""The friction pendulum and the vertical ground motion (the slider on a curved surface, a normal force that varies)."""
