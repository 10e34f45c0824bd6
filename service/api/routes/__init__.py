"""One router per resource; every route has a summary, a stable ``operation_id``, examples and error docs
(:mod:`service.api.openapi`). The routers are wired in :mod:`service.main`."""
