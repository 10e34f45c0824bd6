"""Static files of the service's web page (``index.html``, ``app.js``, ``app.css``).

Served by :mod:`service.api.routes.web` at ``/`` and ``/web/<name>``; plain HTML/JS/CSS, no build step.
"""
