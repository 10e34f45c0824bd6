from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.plan_out import PlanOut
from ...models.plan_request import PlanRequest
from ...types import Response


def _get_kwargs(
    *,
    body: PlanRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/control/plan",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | PlanOut | None:
    if response.status_code == 200:
        response_200 = PlanOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[ErrorOut | PlanOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlanRequest,
) -> Response[ErrorOut | PlanOut]:
    """Rest lengths for a trajectory of tip positions, on one stable branch

     Per step the springs' rest lengths `(L1_0, L2_0)` putting the tip at the target, stable with
    `margin` under the dead tip load, inside `bounds` and within `rate_limit` (length per second) times
    the time since the previous step (`times`, or a fixed `dt`; the start, with the arm's current rest
    lengths `rest_lengths0`, is the state at time 0) (`tensegrity_opt.plan_preloads`): `objective:
    change` is the least change from the previous step (a compiled Newton step on its KKT system, warm-
    started; IPOPT where a bound is active), `margin` / `energy` IPOPT (`preloads_for_pose`). A step no
    admissible rest lengths reach is `feasible: false` with the best reachable pose, and the next step
    starts from the last feasible state (`status: "infeasible_steps"`). `verified`: the forward quasi-
    static solve from the previous step's configuration with the step's rest lengths lands on the
    target, stable. `end_angles` (optional, null entries free) fix the last link's absolute angle. At
    most the server's `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422
    `too_many_steps` naming `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT
    fallback is the same problem). The plan runs in a solver process and stops shortly before the
    server's time limit, answering the steps done (200, `status: "time_limit"`, `success: false`)
    instead of a 504. A step costs ~4 ms by Newton with its verification (n = 4), tens of milliseconds
    by IPOPT; the first plan for a chain length builds its IPOPT problem in one call nothing interrupts
    (n = 40: ~1.5 s; n = 60: ~40 s, a 504, and the process is replaced).

    Args:
        body (PlanRequest): Rest lengths for a trajectory of tip positions, on one stable branch
            (`plan_preloads`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | PlanOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: PlanRequest,
) -> ErrorOut | PlanOut | None:
    """Rest lengths for a trajectory of tip positions, on one stable branch

     Per step the springs' rest lengths `(L1_0, L2_0)` putting the tip at the target, stable with
    `margin` under the dead tip load, inside `bounds` and within `rate_limit` (length per second) times
    the time since the previous step (`times`, or a fixed `dt`; the start, with the arm's current rest
    lengths `rest_lengths0`, is the state at time 0) (`tensegrity_opt.plan_preloads`): `objective:
    change` is the least change from the previous step (a compiled Newton step on its KKT system, warm-
    started; IPOPT where a bound is active), `margin` / `energy` IPOPT (`preloads_for_pose`). A step no
    admissible rest lengths reach is `feasible: false` with the best reachable pose, and the next step
    starts from the last feasible state (`status: "infeasible_steps"`). `verified`: the forward quasi-
    static solve from the previous step's configuration with the step's rest lengths lands on the
    target, stable. `end_angles` (optional, null entries free) fix the last link's absolute angle. At
    most the server's `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422
    `too_many_steps` naming `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT
    fallback is the same problem). The plan runs in a solver process and stops shortly before the
    server's time limit, answering the steps done (200, `status: "time_limit"`, `success: false`)
    instead of a 504. A step costs ~4 ms by Newton with its verification (n = 4), tens of milliseconds
    by IPOPT; the first plan for a chain length builds its IPOPT problem in one call nothing interrupts
    (n = 40: ~1.5 s; n = 60: ~40 s, a 504, and the process is replaced).

    Args:
        body (PlanRequest): Rest lengths for a trajectory of tip positions, on one stable branch
            (`plan_preloads`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | PlanOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlanRequest,
) -> Response[ErrorOut | PlanOut]:
    """Rest lengths for a trajectory of tip positions, on one stable branch

     Per step the springs' rest lengths `(L1_0, L2_0)` putting the tip at the target, stable with
    `margin` under the dead tip load, inside `bounds` and within `rate_limit` (length per second) times
    the time since the previous step (`times`, or a fixed `dt`; the start, with the arm's current rest
    lengths `rest_lengths0`, is the state at time 0) (`tensegrity_opt.plan_preloads`): `objective:
    change` is the least change from the previous step (a compiled Newton step on its KKT system, warm-
    started; IPOPT where a bound is active), `margin` / `energy` IPOPT (`preloads_for_pose`). A step no
    admissible rest lengths reach is `feasible: false` with the best reachable pose, and the next step
    starts from the last feasible state (`status: "infeasible_steps"`). `verified`: the forward quasi-
    static solve from the previous step's configuration with the step's rest lengths lands on the
    target, stable. `end_angles` (optional, null entries free) fix the last link's absolute angle. At
    most the server's `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422
    `too_many_steps` naming `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT
    fallback is the same problem). The plan runs in a solver process and stops shortly before the
    server's time limit, answering the steps done (200, `status: "time_limit"`, `success: false`)
    instead of a 504. A step costs ~4 ms by Newton with its verification (n = 4), tens of milliseconds
    by IPOPT; the first plan for a chain length builds its IPOPT problem in one call nothing interrupts
    (n = 40: ~1.5 s; n = 60: ~40 s, a 504, and the process is replaced).

    Args:
        body (PlanRequest): Rest lengths for a trajectory of tip positions, on one stable branch
            (`plan_preloads`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | PlanOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PlanRequest,
) -> ErrorOut | PlanOut | None:
    """Rest lengths for a trajectory of tip positions, on one stable branch

     Per step the springs' rest lengths `(L1_0, L2_0)` putting the tip at the target, stable with
    `margin` under the dead tip load, inside `bounds` and within `rate_limit` (length per second) times
    the time since the previous step (`times`, or a fixed `dt`; the start, with the arm's current rest
    lengths `rest_lengths0`, is the state at time 0) (`tensegrity_opt.plan_preloads`): `objective:
    change` is the least change from the previous step (a compiled Newton step on its KKT system, warm-
    started; IPOPT where a bound is active), `margin` / `energy` IPOPT (`preloads_for_pose`). A step no
    admissible rest lengths reach is `feasible: false` with the best reachable pose, and the next step
    starts from the last feasible state (`status: "infeasible_steps"`). `verified`: the forward quasi-
    static solve from the previous step's configuration with the step's rest lengths lands on the
    target, stable. `end_angles` (optional, null entries free) fix the last link's absolute angle. At
    most the server's `TENSEGRITY_MAX_TRAJECTORY_STEPS` targets (default 2000; above: 422
    `too_many_steps` naming `targets`), chains of 2 to 60 segments (as `/v1/design/*`: the IPOPT
    fallback is the same problem). The plan runs in a solver process and stops shortly before the
    server's time limit, answering the steps done (200, `status: "time_limit"`, `success: false`)
    instead of a 504. A step costs ~4 ms by Newton with its verification (n = 4), tens of milliseconds
    by IPOPT; the first plan for a chain length builds its IPOPT problem in one call nothing interrupts
    (n = 40: ~1.5 s; n = 60: ~40 s, a 504, and the process is replaced).

    Args:
        body (PlanRequest): Rest lengths for a trajectory of tip positions, on one stable branch
            (`plan_preloads`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | PlanOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
