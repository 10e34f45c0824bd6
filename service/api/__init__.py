"""The HTTP layer: routes (one router per resource), their dependencies and limits (:mod:`.deps`), the dispatcher
of their tasks (:mod:`.dispatch`), failures as HTTP answers (:mod:`.errors`), the OpenAPI words (:mod:`.openapi`),
the middleware, metrics, connection limits (:mod:`.connections`) and the offline API docs (:mod:`.swagger`)."""
