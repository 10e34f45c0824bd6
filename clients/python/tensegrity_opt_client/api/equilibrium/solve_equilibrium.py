from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.equilibrium_out import EquilibriumOut
from ...models.equilibrium_request import EquilibriumRequest
from ...models.error_out import ErrorOut
from ...types import Response


def _get_kwargs(
    *,
    body: EquilibriumRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/equilibrium",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> EquilibriumOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = EquilibriumOut.from_dict(response.json())

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


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[EquilibriumOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: EquilibriumRequest,
) -> Response[EquilibriumOut | ErrorOut]:
    """Least-energy stable equilibrium for a tip deflection

     The least-energy **stable** equilibrium with the tip held at `(2 sum(b) - dx, dy)`
    (`tensegrity_opt.solve_equilibrium`). `q0` (optional) is a nearby configuration, e.g. the previous
    answer of a control loop; it competes with the global search. With `local: true` only the local
    solve from `q0` runs: the equilibrium on the branch through `q0` (read `stable`), what a control
    loop following its arm wants, much cheaper than the search. With `certify: true` the answer carries
    `certificate`, a rigorous lower bound on the energy of every configuration meeting the tip
    constraint and its gap (`status` `certified` when within tolerance).

    Args:
        body (EquilibriumRequest): Least-energy stable equilibrium with the tip held at `(2 sum(b)
            - dx, dy)`.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[EquilibriumOut | ErrorOut]
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
    body: EquilibriumRequest,
) -> EquilibriumOut | ErrorOut | None:
    """Least-energy stable equilibrium for a tip deflection

     The least-energy **stable** equilibrium with the tip held at `(2 sum(b) - dx, dy)`
    (`tensegrity_opt.solve_equilibrium`). `q0` (optional) is a nearby configuration, e.g. the previous
    answer of a control loop; it competes with the global search. With `local: true` only the local
    solve from `q0` runs: the equilibrium on the branch through `q0` (read `stable`), what a control
    loop following its arm wants, much cheaper than the search. With `certify: true` the answer carries
    `certificate`, a rigorous lower bound on the energy of every configuration meeting the tip
    constraint and its gap (`status` `certified` when within tolerance).

    Args:
        body (EquilibriumRequest): Least-energy stable equilibrium with the tip held at `(2 sum(b)
            - dx, dy)`.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        EquilibriumOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: EquilibriumRequest,
) -> Response[EquilibriumOut | ErrorOut]:
    """Least-energy stable equilibrium for a tip deflection

     The least-energy **stable** equilibrium with the tip held at `(2 sum(b) - dx, dy)`
    (`tensegrity_opt.solve_equilibrium`). `q0` (optional) is a nearby configuration, e.g. the previous
    answer of a control loop; it competes with the global search. With `local: true` only the local
    solve from `q0` runs: the equilibrium on the branch through `q0` (read `stable`), what a control
    loop following its arm wants, much cheaper than the search. With `certify: true` the answer carries
    `certificate`, a rigorous lower bound on the energy of every configuration meeting the tip
    constraint and its gap (`status` `certified` when within tolerance).

    Args:
        body (EquilibriumRequest): Least-energy stable equilibrium with the tip held at `(2 sum(b)
            - dx, dy)`.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[EquilibriumOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: EquilibriumRequest,
) -> EquilibriumOut | ErrorOut | None:
    """Least-energy stable equilibrium for a tip deflection

     The least-energy **stable** equilibrium with the tip held at `(2 sum(b) - dx, dy)`
    (`tensegrity_opt.solve_equilibrium`). `q0` (optional) is a nearby configuration, e.g. the previous
    answer of a control loop; it competes with the global search. With `local: true` only the local
    solve from `q0` runs: the equilibrium on the branch through `q0` (read `stable`), what a control
    loop following its arm wants, much cheaper than the search. With `certify: true` the answer carries
    `certificate`, a rigorous lower bound on the energy of every configuration meeting the tip
    constraint and its gap (`status` `certified` when within tolerance).

    Args:
        body (EquilibriumRequest): Least-energy stable equilibrium with the tip held at `(2 sum(b)
            - dx, dy)`.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        EquilibriumOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
